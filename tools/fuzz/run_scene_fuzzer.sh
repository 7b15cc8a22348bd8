#!/usr/bin/env bash
# Fuzz the scene loader with libFuzzer for a given time (issue 16; not part
# of `make test`):   tools/fuzz/run_scene_fuzzer.sh [SECONDS] [JOBS]
# Builds build-fuzz/ with clang, ASan + UBSan and coverage instrumentation,
# seeds the corpus with every scene of the repository (and ../shared/scenes
# when present), then runs until SECONDS have passed (default 1800). Prints
# libFuzzer's statistics; findings are written to build-fuzz/fuzz-findings/.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-1800}
jobs=${2:-1}
build=build-fuzz
command -v clang++ >/dev/null || { echo "error: clang++ is needed (apt-get install clang)" >&2; exit 1; }
if [ ! -f $build/build.ninja ]; then
  cmake -S . -B $build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DFEMTO_FUZZ=ON -DFEMTO_BUILD_TESTS=OFF
fi
cmake --build $build -j "$(nproc)" --target femto_fuzz_scene_loader femto_render

corpus=$build/fuzz-corpus
# Includes and meshes the seeds name resolve here. Three folders deep, so
# that the seed scenes' ../../../shared/meshes (the 350k-triangle Armadillo)
# resolve to nothing: loading it under ASan takes over the 10 s timeout, a
# slow valid input rather than a hang (the first run's only finding).
base=$build/fuzz-base/a/b/c
mkdir -p $corpus $base $build/fuzz-findings
# Seeds: every XML scene we have, each flattened into the corpus (name = hash).
seed_dirs=(scenes tests/scene/dialects tests/cli)
[ -d ../shared/scenes ] && seed_dirs+=(../shared/scenes)
find "${seed_dirs[@]}" -name '*.xml' -size -64k -print0 | while IFS= read -r -d '' f; do
  cp "$f" "$corpus/$(sha1sum "$f" | cut -c1-16).xml"
  cp -n "$(dirname "$f")"/*.xml "$(dirname "$f")"/*.obj "$(dirname "$f")"/*.ply $base/ 2>/dev/null || true
done
# A dictionary of the loader's vocabulary helps mutations reach deep code.
dict=$build/fuzz-scene.dict
grep -ohE '(name|type|value|id|version|filename)="[A-Za-z_0-9.]{1,24}"' $corpus/*.xml | sort -u | sed 's/"/\\"/g; s/.*/"&"/' > $dict
printf '"<scene version=\\"3.0.0\\">"\n"</scene>"\n"<include filename=\\""\n"<ref id=\\""\n"<default name=\\""\n"$"\n"NaN"\n"inf"\n"-1e300"\n' >> $dict

export FEMTO_PLUGIN_PATH=$build/bin/plugins FEMTO_FUZZ_BASE_DIR=$base
# The shared sanitizer runtime (-shared-libsan) lives in clang's own folder.
export LD_LIBRARY_PATH="$(dirname "$(clang++ -print-file-name=libclang_rt.asan-x86_64.so)")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# The executable links the runtime after libfuzzer's own: order check off (the runtime is the shared one).
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:verify_asan_link_order=0 UBSAN_OPTIONS=print_stacktrace=1
# -timeout: a scene that takes 10 s to load is a hang; -rss_limit_mb and
# -malloc_limit_mb: a scene asking for more is the bad_alloc we must not have.
# Several jobs fork workers that log to fuzz-N.log; one runs in this process.
parallel=()
[ "$jobs" -gt 1 ] && parallel=(-jobs="$jobs" -workers="$jobs")
$build/bin/femto_fuzz_scene_loader $corpus -dict=$dict -max_total_time="$seconds" "${parallel[@]}" \
  -timeout=10 -rss_limit_mb=4096 -malloc_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
  -artifact_prefix=$build/fuzz-findings/ 2>&1 | tee $build/fuzz.log | grep -E '^#|stat::|ERROR|SUMMARY|Done' | tail -40
