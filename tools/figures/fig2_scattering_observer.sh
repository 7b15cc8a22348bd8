#!/bin/sh
# Seed figure 2: single vs multiple scattering in the fog-filled Cornell box
# with a glass ball and a mirror ball, with and without observer time, frames
# side by side (scenes/seed-glass-mirror-balls). Four renders per integrator,
# then one PNG per integrator with one exposure:
#   out/fig2/fig2_scattering_observer.png        transient_path, single = max_depth 2
#   out/fig2/fig2_scattering_observer_beams.png  transient_beams, single = store=single
# Usage (from the repository root, after building femto and its plugins):
#   tools/figures/fig2_scattering_observer.sh [extra femto options for every render]
# Environment: FEMTO (default build/bin/femto), OUT (default out/fig2),
# SPP (transient_path's samples per pixel, 64), RES (96), BINS (128),
# BIN_WIDTH (0.05), INTEGRATORS ("transient_path transient_beams"), DOCS
# (e.g. docs/images: also write smaller copies of the PNGs there).
# transient_beams' budget (passes, photons, radii) is the scene's
# integrator-transient_beams.xml; override with e.g. -D passes=8.
OUT_DEFAULT=out/fig2 SPP_DEFAULT=64 RES_DEFAULT=96
. tools/figures/common.sh
BINS=${BINS:-128}
BIN_WIDTH=${BIN_WIDTH:-0.05}
SCENE=scenes/seed-glass-mirror-balls/scene.xml

# Without observer time the window starts at OPL 0 (the light itself); with
# it, at 3.4: the camera is 2.9 to 4.9 from the fog it sees (3.9 from the
# room's centre), so a column shows about the same moment of the light's
# travel in both rows, delayed by the camera segment (the observer-time rows
# lag at the back of the room, lead at the front).
render() {  # name observer_time start [femto options]
  name=$1 observer=$2 start=$3
  shift 3
  timed_render "$name" "$SCENE" -D observer_time="$observer" -D start="$start" \
    -D resolution="$RES" -D bins="$BINS" -D bin_width="$BIN_WIDTH" "$@"
}

# figure PNG INTEGRATOR-LABEL PREFIX: the four renders PREFIX{single,multiple}_{observer,local}, columns at
# the elapsed OPL since each window's start (observer-time rows: OPL 3.4 + t).
figure() {
  /usr/bin/python3 tools/figures/frame_strip.py "$OUT/$1" \
    "single, observer time=$OUT/${3}single_observer.npy@3.4" \
    "multiple, observer time=$OUT/${3}multiple_observer.npy@3.4" \
    "single, no observer time=$OUT/${3}single_local.npy@0" \
    "multiple, no observer time=$OUT/${3}multiple_local.npy@0" \
    --bin-width "$BIN_WIDTH" --times 0.4 0.8 1.2 1.6 2.0 2.6 --average 3 --steady \
    --title "Seed fig. 2: glass ball (top) + mirror ball (bottom) in fog, $2, ${RES}x$RES"
  publish "$OUT/$1"
}

# transient_path: single scattering is max_depth 2 (one scattering vertex
# before the light; specular bounces count, so the balls are dark), multiple 12.
if wants transient_path; then
  for observer in true false; do
    start=3.4 where=observer
    [ "$observer" = true ] || start=0 where=local
    render "single_$where" "$observer" "$start" -D max_depth=2 -D spp="$SPP" "$@"
    render "multiple_$where" "$observer" "$start" -D max_depth=12 -D spp="$SPP" "$@"
  done
  figure fig2_scattering_observer.png "transient_path, $SPP spp" ""
fi

# transient_beams: single scattering is store=single (only beams of photons
# that have not scattered yet, through the balls' specular chains too: the
# paper's split of the medium's radiance), multiple store=all; max_depth 12.
if wants transient_beams; then
  for observer in true false; do
    start=3.4 where=observer
    [ "$observer" = true ] || start=0 where=local
    render "beams_single_$where" "$observer" "$start" -D integrator=transient_beams -D store=single "$@"
    render "beams_multiple_$where" "$observer" "$start" -D integrator=transient_beams -D store=all "$@"
  done
  figure fig2_scattering_observer_beams.png "transient_beams (scene's integrator-transient_beams.xml)" beams_
  # Animated, left to right: single and multiple scattering with observer
  # time, then without (each frame the mean of 4 bins: 32 frames, ~1 MB).
  sequence_gif fig2_scattering_observer_beams 4 0:$((BINS / 4)) "$OUT/beams_single_observer.npy" \
    "$OUT/beams_multiple_observer.npy" "$OUT/beams_single_local.npy" "$OUT/beams_multiple_local.npy"
fi
