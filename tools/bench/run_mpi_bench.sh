#!/bin/sh
# Regenerates the MPI section of docs/BENCHMARKS.md: one process against
# `mpirun -n 2` (one thread per rank, so 1 -> 2 ranks is the only change) on
# scenes/cornell-box-fog, transient_path and transient_beams, at 128x128 x 1024
# bins (RUNS runs each, interleaved, medians) and 512x512 x 4096 bins (a
# 12.9 GB volume; LARGE_RUNS runs each, default 1). Also measured:
#   - the machine's own ceiling: two independent one-process renders at once
#     (2 cores shared by two processes run each slower than one alone);
#   - what rank 0 does for the other ranks per tile, and the bytes the ranks
#     exchange per pass (rank 0's debug log), for the scaling model below;
#   - what a pass costs per bin-pixel to fold into a 4096-bin volume (one
#     process, 1 against 3 passes of almost no camera work);
#   - start-up: a job with next to nothing to render.
# Efficiency: T(1 process) / (2 x T(2 ranks)), by wall time (idle machine)
# and by CPU time (the job's: mpirun and every rank).
#   tools/bench/run_mpi_bench.sh [build-dir]      (default: build)
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
runs=${RUNS:-3}
large_runs=${LARGE_RUNS:-1}
cd "$root"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target femto_render >/dev/null
femto="$build/bin/femto"
scene=scenes/cornell-box-fog/scene.xml
command -v mpirun >/dev/null || { echo "needs mpirun (Debian: openmpi-bin)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian package: time)" >&2; exit 1; }
mpirun="mpirun --oversubscribe --mca btl self,vader -x FEMTO_LOG_LEVEL"
[ "$(id -u)" -ne 0 ] || export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export FEMTO_LOG_LEVEL=debug
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
load_start=$(cut -d' ' -f1-3 /proc/loadavg)

# run NAME RANKS ARGS...: one render (RANKS 0: no mpirun); appends
# "cpu wall" to $work/NAME and keeps the log in $work/NAME.log.
run() {
  name=$1 ranks=$2
  shift 2
  if [ "$ranks" -eq 0 ]; then launch=""; else launch="$mpirun -n $ranks"; fi
  # shellcheck disable=SC2086
  /usr/bin/time -f "%U %S %e" -o "$work/time" $launch "$femto" render "$scene" -t 1 --no-progress \
    -o "$work/$name.exr" "$@" >"$work/$name.log" 2>&1
  awk '{ printf "%.2f %.2f\n", $1 + $2, $3 }' "$work/time" >> "$work/$name"
}
# both NAME ARGS...: two one-process renders at once; appends the wall time of the later.
both() {
  name=$1
  shift
  start=$(date +%s.%N)
  "$femto" render "$scene" -t 1 --no-progress -o "$work/${name}a.exr" "$@" >/dev/null 2>&1 &
  "$femto" render "$scene" -t 1 --no-progress -o "$work/${name}b.exr" "$@" >/dev/null 2>&1
  wait
  awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "0 %.2f\n", b - a }' >> "$work/$name"
  rm -f "$work/${name}"[ab].*
}
# same NAME: the volumes of 1 process and 2 ranks are the same bits (then removed: 12.9 GB each when large).
same() {
  cmp -s "$work/${1}1.npy" "$work/${1}2.npy" || { echo "$1: 2 ranks wrote other bits than 1 process" >&2; exit 1; }
  rm -f "$work/${1}1.npy" "$work/${1}2.npy"
}
# pair CASE: the render $CASE on one process, then on 2 ranks, compared.
pair() {
  eval "args=\$$1"
  # shellcheck disable=SC2086
  run "${1}1" 0 $args
  # shellcheck disable=SC2086
  run "${1}2" 2 $args
  same "$1"
}
median() { cut -d' ' -f"$2" "$1" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
runs_of() { cut -d' ' -f"$2" "$1" | tr '\n' ' ' | sed 's/ $//'; }

path_small="-D resolution=128 -D bins=1024 -D bin_width=0.01 -D spp=128"
beams_small="-D integrator=transient_beams -D resolution=128 -D bins=1024 -D bin_width=0.01 -D passes=16"
path_large="-D resolution=512 -D bins=4096 -D bin_width=0.0025 -D spp=32"
beams_large="-D integrator=transient_beams -D resolution=512 -D bins=4096 -D bin_width=0.0025 -D passes=2"
fold_args="-D integrator=transient_beams -D resolution=64 -D bins=4096 -D bin_width=0.0025 -D spp=1 -D photon_count=1000 -D beam_photon_count=100"
# Next to nothing to render: what starting a job costs (loading plugins and scene, MPI_Init).
start_args="-D resolution=8 -D bins=16 -D bin_width=0.64 -D spp=1"
i=0
while [ "$i" -lt "$runs" ]; do
  pair path_small
  pair beams_small
  # shellcheck disable=SC2086
  both path_small_both $path_small
  # shellcheck disable=SC2086
  run fold1 0 $fold_args -D passes=1
  # shellcheck disable=SC2086
  run fold3 0 $fold_args -D passes=3
  # shellcheck disable=SC2086
  run start1 0 $start_args
  # shellcheck disable=SC2086
  run start2 2 $start_args
  i=$((i + 1))
done
i=0
while [ "$i" -lt "$large_runs" ]; do
  pair path_large
  pair beams_large
  i=$((i + 1))
done
# The disk the volumes go to: 2 GB written and flushed (a 512x512 x 4096 volume is 12.9 GB,
# more than the page cache holds dirty, so its passes wait on the disk).
disk=$(dd if=/dev/zero of="$work/disk" bs=1M count=2048 conv=fdatasync 2>&1 | sed -n 's/.*, \([0-9.]* [MG]B\/s\)$/\1/p')
rm -f "$work/disk"
load_end=$(cut -d' ' -f1-3 /proc/loadavg)
. tools/bench/provenance.sh
# ratio NAME FIELD: by wall time (field 2) T(1) / (2 T(2)); by CPU time (field 1,
# already summed over the ranks) CPU(1) / CPU(2).
ratio() {
  awk -v a="$(median "$work/${1}1" "$2")" -v b="$(median "$work/${1}2" "$2")" -v field="$2" \
    'BEGIN { printf "%.2f", a / ((field == 2 ? 2 : 1) * b) }'
}
# rank0 NAME: rank 0's coordination per tile and the image bytes exchanged per pass (first pass).
rank0() {
  us=$(sed -n 's/.*rank 0 spent \([0-9.e+-]*\) us of CPU per tile of theirs.*/\1/p' "$work/${1}2.log" | awk '{ s += $1; n++ } END { if (n) printf "%.1f", s / n }')
  bytes=$(sed -n 's/.*stored image pixels (\([0-9]*\) bytes).*/\1/p' "$work/${1}2.log" | head -n 1)
  tiles=$(sed -n 's/.*tiles rendered by ranks 0 to 1: \([0-9]*\) \([0-9]*\);.*/\1 + \2/p' "$work/${1}2.log" | head -n 1)
  msg=$(sed -n 's/.*messages, \([0-9.e+-]*\) us each.*/\1/p' "$work/${1}2.log" | awk '{ s += $1; n++ } END { if (n) printf "%.1f", s / n }')
  echo "$us us of CPU per tile of rank 1, $msg us per message ($tiles tiles a pass); $bytes B of images a pass"
}
out=docs/BENCHMARKS.md
{
  echo "## MPI: one process against two ranks"
  echo
  echo "Generated by \`tools/bench/run_mpi_bench.sh\` — do not edit this section by hand; rerun the script."
  echo
  echo "- machine: $model, $(nproc) logical CPUs available; one thread per rank (\`-t 1\`), Open MPI $(mpirun --version | sed -n 's/.*Open MPI) //p'), shared memory between the ranks"
  echo "- load average (1, 5, 15 min) at the start: $load_start; at the end: $load_end"
  echo "- commit: $commit$dirty, $(date -u +%Y-%m-%d)"
  echo "- command: \`tools/bench/run_mpi_bench.sh\` ($runs runs per 128x128 case, $large_runs per 512x512 case, medians; the volumes of 1 and 2 ranks compared bit for bit)"
  echo "- disk of the output folder: $disk (2 GB written with \`dd conv=fdatasync\`); RAM $(free -g | awk '/^Mem:/ { print $2 }') GiB"
  echo "- **efficiency** = wall time of 1 process / (2 x wall time of 2 ranks), and CPU time of 1 process / CPU time of"
  echo "  the 2-rank job (mpirun and both ranks)."
  echo "  Each rank stores the tiles it renders into the one volume; rank 0 only hands out tiles."
  echo
  echo "| render | wall 1 process (s) | wall 2 ranks (s) | **efficiency (wall)** | CPU 1 (s) | CPU 2 (s) | efficiency (CPU) | rank 0 for the others |"
  echo "|---|---|---|---|---|---|---|---|"
  for case in path_small beams_small path_large beams_large; do
    eval "args=\$$case"
    case $case in path*) label=transient_path ;; *) label=transient_beams ;; esac
    echo "| $label \`$args\` | $(median "$work/${case}1" 2) | $(median "$work/${case}2" 2) | **$(ratio "$case" 2)** | $(median "$work/${case}1" 1) | $(median "$work/${case}2" 1) | $(ratio "$case" 1) | $(rank0 "$case") |"
  done
  echo
  ceiling=$(awk -v a="$(median "$work/path_small1" 2)" -v b="$(median "$work/path_small_both" 2)" 'BEGIN { printf "%.2f", a / b }')
  echo "The machine's own ceiling: two independent one-process renders of the 128x128 transient_path case at once"
  echo "take $(median "$work/path_small_both" 2) s of wall time against $(median "$work/path_small1" 2) s alone (runs: $(runs_of "$work/path_small_both" 2)): **$ceiling**,"
  echo "what two ranks could reach at best here (two processes on the 2 cores run each slower than one alone)."
  echo "Against that ceiling, the wall efficiencies above read: $(for case in path_small beams_small path_large beams_large; do
    printf '%s %s; ' "$case" "$(awk -v e="$(ratio "$case" 2)" -v c="$ceiling" 'BEGIN { printf "%.2f", e / c }')"; done)"
  echo
  echo "Start-up (\`$start_args\`): wall $(median "$work/start1" 2) s for one process, $(median "$work/start2" 2) s for two ranks (mpirun);"
  echo "CPU $(median "$work/start1" 1) s and $(median "$work/start2" 1) s."
  echo
  fold_ns=$(awk -v a="$(median "$work/fold1" 1)" -v b="$(median "$work/fold3" 1)" 'BEGIN { printf "%.1f", (b - a) / 2 / (64 * 64 * 4096) * 1e9 }')
  echo "Folding a pass into a 4096-bin volume (\`$fold_args\`, passes 1 against 3; one process):"
  echo "CPU $(median "$work/fold1" 1) s and $(median "$work/fold3" 1) s, so **$fold_ns ns per pass and bin-pixel** (runs: $(runs_of "$work/fold1" 1); $(runs_of "$work/fold3" 1));"
  echo "it includes the pass's 1 spp camera work and photons, so it is an upper bound. Each rank folds the tiles it rendered."
  echo
  echo "Wall times of the runs (s), 1 process; 2 ranks:"
  for case in path_small beams_small path_large beams_large; do
    echo "$case $(runs_of "$work/${case}1" 2); $(runs_of "$work/${case}2" 2)."
  done
  echo "One process, transient_beams 128x128 summary: $(grep -m1 'transient_beams: [0-9]* passes' "$work/beams_small1.log")"
} | /usr/bin/python3 tools/bench/benchmarks.py set mpi-scaling
echo "wrote the mpi-scaling section of $out (load average at the end: $load_end)"
