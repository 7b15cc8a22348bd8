#!/bin/sh
# Seed figure 3: Dirac vs continuous emission on the coloured mirrors and the
# glass-ball caustic (scenes/seed-coloured-mirrors-caustic), frames side by
# side with the steady image, two rows per integrator (transient_path, then
# transient_beams): out/fig3/fig3_dirac_continuous.png
# Two renders per integrator, same scene and seed: the light's pulse a Dirac
# at OPL 0 (-D pulse=delta), then continuous emission switched on at OPL 0
# (-D pulse=continuous: each frame is the running integral of the Dirac
# sequence averaged over the bin, exact; tested in
# tests/unit/scenes/test_seed_scenes.cpp). A continuous row's steady column is its
# last frame.
# Usage: tools/figures/fig3_dirac_continuous.sh [extra femto options for every render]
# Environment: FEMTO (build/bin/femto), OUT (out/fig3), SPP (transient_path's
# samples per pixel, 256), RES (128, height 3/4), INTEGRATORS
# ("transient_path transient_beams"), DOCS (e.g. docs/images: also write a
# smaller copy of the PNG there). transient_beams' budget is the scene's
# integrator-transient_beams.xml (override with e.g. -D passes=8).
OUT_DEFAULT=out/fig3 SPP_DEFAULT=256 RES_DEFAULT=128
. tools/figures/common.sh
rows=""
for integrator in transient_path transient_beams; do
  wants "$integrator" || continue
  prefix="" options="-D spp=$SPP"
  [ "$integrator" = transient_path ] || prefix=beams_ options="-D integrator=$integrator"
  for pulse in delta continuous; do
    # shellcheck disable=SC2086  # $options holds two words on purpose
    timed_render "$prefix$pulse" scenes/seed-coloured-mirrors-caustic/scene.xml $options \
      -D resolution="$RES" -D height=$((RES * 3 / 4)) -D pulse="$pulse" "$@"
  done
  rows="$rows|Dirac, $integrator=$OUT/${prefix}delta.npy@6|continuous, $integrator=$OUT/${prefix}continuous.npy@6#continuous"
done
# Window: OPL 6 + 120 bins of 0.05. Columns: the floor lit directly (+1.6),
# the caustic under the ball (+2.7), its reflections in the mirrors (+3.4 .. +4.2).
IFS='|'
# shellcheck disable=SC2086  # split $rows on '|' into one argument per row
/usr/bin/python3 tools/figures/frame_strip.py "$OUT/fig3_dirac_continuous.png" ${rows#|} \
  --bin-width 0.05 --times 1.6 2.2 2.7 3.1 3.5 4.0 5.9 --average 3 --row-exposure --steady \
  --title "Seed fig. 3: coloured mirrors and a glass-ball caustic (IOR 1.5); transient_path $SPP spp, transient_beams as in its integrator file"
publish "$OUT/fig3_dirac_continuous.png"
# Animated with transient_beams (when rendered), left to right: Dirac,
# continuous, each at its own exposure (as the figure's rows).
if wants transient_beams; then
  sequence_gif fig3_dirac_continuous_beams 2 0:60 --each-exposure "$OUT/beams_delta.npy" "$OUT/beams_continuous.npy"
fi
