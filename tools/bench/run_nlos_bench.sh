#!/bin/sh
# Times a 64 x 64-point confocal NLOS capture with 512 bins of the hidden T
# (tools/nlos/hidden_letter.xml: laser and hidden-geometry sampling, third
# bounce only) at SPP samples per point (default 256), RUNS times (default 3)
# after one warm-up; prints the median CPU time (user + system, the measure
# that stays meaningful on a shared machine) and wall time, with the commit,
# CPU model and load average (docs/nlos.md, "Cost").
#   tools/bench/run_nlos_bench.sh [build-dir]
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
runs=${RUNS:-3}
spp=${SPP:-256}
cd "$root"
. tools/bench/provenance.sh
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target femto transient_nlos_path nlos_capture_meter projector diffuse rectangle \
  independent transient_hdr_film box >/dev/null
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian package: time)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
render() {
  /usr/bin/time -f "%U %S %e" -o "$work/time" "$build/bin/femto" render tools/nlos/hidden_letter.xml --strict \
    -D spp="$spp" -t 2 --no-progress -p "$build/bin/plugins" -o "$work/capture.exr" >/dev/null
}
render  # warm-up
i=0
while [ "$i" -lt "$runs" ]; do
  render
  awk '{ printf "%.3f %.3f\n", $1 + $2, $3 }' "$work/time" >> "$work/runs"
  i=$((i + 1))
done
median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
cpu=$(cut -d' ' -f1 "$work/runs" | median)
wall=$(cut -d' ' -f2 "$work/runs" | median)
echo "confocal 64x64 points, 512 bins, $spp spp, 2 threads: median of $runs runs: cpu $cpu s, wall $wall s"
echo "commit $commit$dirty, $model, load average at start $load_start, at end $(cut -d' ' -f1-3 /proc/loadavg)"
