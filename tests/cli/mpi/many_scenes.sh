#!/usr/bin/env bash
# `mpirun -n 2 femto render` with more scenes than ranks: each rank renders
# whole scenes alone, into the folder -o names; every file is byte-equal to
# the one process's, and --resume skips them all on a second run.
#   many_scenes.sh FEMTO PLANE_SCENE OUT_DIR
set -u
femto=$1 plane=$2 out=$3
. "$(dirname "$0")/mpi_env.sh"
rm -rf "$out" && mkdir -p "$out/scenes"
scenes=()
for k in 0 1 2 3 4; do
  sed "s/origin=\"0, 0, 2\"/origin=\"0, 0, 2.$k\"/" "$plane" >"$out/scenes/plane$k.xml"
  scenes+=("$out/scenes/plane$k.xml")
done
opts=(--no-progress -t 1 -D resolution=24 -D bins=32 -D spp=16)
"$femto" render "${scenes[@]}" -o "$out/one" "${opts[@]}" >"$out/one.log" 2>&1 ||
  { cat "$out/one.log"; echo "the single-process render failed"; exit 1; }
"${mpirun_cmd[@]}" -n 2 "$femto" render "${scenes[@]}" -o "$out/two" --resume "${opts[@]}" >"$out/two.log" 2>&1 ||
  { cat "$out/two.log"; echo "mpirun -n 2 failed"; exit 1; }
status=0
[ "$(grep -c '^rendered ' "$out/two.log")" -eq 5 ] || { echo "expected 5 summary lines:"; cat "$out/two.log"; status=1; }
files=$(cd "$out/one" && find . -type f | sort)
got=$(cd "$out/two" && find . -type f ! -name '*.femto-done' | sort)
[ "$got" = "$files" ] || { echo "other files:"; diff <(echo "$files") <(echo "$got"); status=1; }
for f in $files; do
  cmp -s "$out/one/$f" "$out/two/$f" || { echo "$f differs from one process"; status=1; }
done
"${mpirun_cmd[@]}" -n 2 "$femto" render "${scenes[@]}" -o "$out/two" --resume "${opts[@]}" >"$out/again.log" 2>&1 ||
  { cat "$out/again.log"; echo "the resumed mpirun failed"; exit 1; }
[ "$(grep -c '^skipped ' "$out/again.log")" -eq 5 ] || { echo "expected 5 skipped scenes:"; cat "$out/again.log"; status=1; }
[ $status -eq 0 ] && echo "5 scenes on 2 ranks: $(echo "$files" | wc -l) files identical to one process; resumed: all skipped"
exit $status
