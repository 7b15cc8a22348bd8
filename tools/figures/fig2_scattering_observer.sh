#!/bin/sh
# Seed figure 2: single vs multiple scattering in the fog-filled Cornell box
# with a glass ball and a mirror ball, with and without observer time, frames
# side by side (scenes/seed-glass-mirror-balls). Four renders with
# transient_path at a small budget, then one PNG with one exposure:
#   out/fig2/fig2_scattering_observer.png
# Usage (from the repository root, after building femto and its plugins):
#   tools/figures/fig2_scattering_observer.sh [extra femto options, e.g. -D integrator=transient_beams]
# Environment: FEMTO (default build/bin/femto), OUT (default out/fig2),
# SPP (64), RES (96), BINS (128), BIN_WIDTH (0.05).
OUT_DEFAULT=out/fig2 SPP_DEFAULT=64 RES_DEFAULT=96
. tools/figures/common.sh
BINS=${BINS:-128}
BIN_WIDTH=${BIN_WIDTH:-0.05}
SCENE=scenes/seed-glass-mirror-balls/scene.xml

# Single scattering: max_depth 2 (one scattering vertex before the light);
# multiple: 12. Without observer time the window starts at OPL 0 (the light
# itself); with it, at 3.4: the camera is 2.9 to 4.9 from the fog it sees
# (3.9 from the room's centre), so a column shows about the same moment of
# the light's travel in both rows, delayed by the camera segment (the
# observer-time rows lag at the back of the room, lead at the front).
# Extra options given to this script pass through to every render.
render() {  # name max_depth observer_time start [extra options]
  name=$1 depth=$2 observer=$3 start=$4
  shift 4
  timed_render "$name" "$SCENE" -D max_depth="$depth" -D observer_time="$observer" -D start="$start" \
    -D spp="$SPP" -D resolution="$RES" -D bins="$BINS" -D bin_width="$BIN_WIDTH" "$@"
}
render single_observer 2 true 3.4 "$@"
render multiple_observer 12 true 3.4 "$@"
render single_local 2 false 0 "$@"
render multiple_local 12 false 0 "$@"

# Columns: elapsed OPL since each window's start (observer-time rows: OPL 3.4 + t).
/usr/bin/python3 tools/figures/frame_strip.py "$OUT/fig2_scattering_observer.png" \
  "single, observer time=$OUT/single_observer.npy@3.4" \
  "multiple, observer time=$OUT/multiple_observer.npy@3.4" \
  "single, no observer time=$OUT/single_local.npy@0" \
  "multiple, no observer time=$OUT/multiple_local.npy@0" \
  --bin-width "$BIN_WIDTH" --times 0.4 0.8 1.2 1.6 2.0 2.6 --average 3 --steady \
  --title "Seed fig. 2: glass ball (top) + mirror ball (bottom) in fog, transient_path, $SPP spp, ${RES}x$RES"
