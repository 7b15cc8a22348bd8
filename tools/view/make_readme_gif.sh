#!/usr/bin/env bash
# Regenerate the README's animation: scenes/cornell-box-fog rendered small with
# a transient integrator, its time bins turned into a GIF by `femto frames`.
#   tools/view/make_readme_gif.sh                      # transient_path, 256 spp
#   INTEGRATOR=transient_beams SPP=16 tools/view/make_readme_gif.sh
# Settings (environment): INTEGRATOR, SPP, RESOLUTION, BINS, EVERY (keep every
# K-th bin), FPS, THREADS, FEMTO (the femto program), OUT (the GIF). Prints the
# caption line for README.md (scene, integrator, spp, time, machine).
# Needs ffmpeg (tools/install-deps.sh installs it). Keep the GIF under ~1.5 MB:
# raise EVERY or lower RESOLUTION if it grows.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
femto=${FEMTO:-$root/build/bin/femto}
integrator=${INTEGRATOR:-transient_path}
spp=${SPP:-256}
resolution=${RESOLUTION:-128}
bins=${BINS:-128}
every=${EVERY:-1}
fps=${FPS:-15}
out=${OUT:-$root/docs/images/cornell-box-fog.gif}
threads=${THREADS:-0}

# The scene's window is OPL 3 to 13.24 (see its header): keep it whatever BINS is.
bin_width=$(awk "BEGIN { print 10.24 / $bins }")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
thread_args=()
[ "$threads" -gt 0 ] && thread_args=(-t "$threads")

start=$(date +%s.%N)
"$femto" render "$root/scenes/cornell-box-fog/scene.xml" -o "$work/fog.exr" --no-progress --strict "${thread_args[@]}" \
  -D integrator="$integrator" -D spp="$spp" -D resolution="$resolution" -D bins="$bins" -D bin_width="$bin_width"
seconds=$(awk "BEGIN { printf \"%.0f\", $(date +%s.%N) - $start }")
"$femto" frames "$work/fog.npy" -o "$work/frames" --every "$every" --gif --fps "$fps"
mkdir -p "$(dirname "$out")"
cp "$work/frames/sequence.gif" "$out"

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
cores=$(nproc)
size=$(du -k "$out" | cut -f1)
echo "wrote $out (${size} KiB)"
echo "caption: scenes/cornell-box-fog, ${resolution}x${resolution}, $integrator, $spp spp, $bins bins of OPL $bin_width" \
  "(every $every shown at $fps fps); rendered in ${seconds} s on $cores threads of $cpu"
