#!/bin/sh
# Seed figure 4: a glass Armadillo under a Dirac pulse, the steady image beside
# its frames (scenes/seed-glass-armadillo), one row per integrator
# (transient_path, transient_beams): out/fig4/fig4_glass_armadillo.png
# Uses ../shared/meshes/armadillo.obj when present (research-use licence, never
# committed); otherwise generates the fallback creature with
# tools/scenes/make_blob_mesh.py and says so under the figure.
# Usage: tools/figures/fig4_glass_armadillo.sh [extra femto options for every render]
# Environment: FEMTO (build/bin/femto), OUT (out/fig4), SPP (transient_path's
# samples per pixel, 128), RES (128, height 3/4), INTEGRATORS
# ("transient_path transient_beams"), DOCS (e.g. docs/images: also write a
# smaller copy of the PNG there). transient_beams' budget is the scene's
# integrator-transient_beams.xml (override with e.g. -D passes=8).
OUT_DEFAULT=out/fig4 SPP_DEFAULT=128 RES_DEFAULT=128
. tools/figures/common.sh
mesh=$(cd .. && pwd)/shared/meshes/armadillo.obj
note="mesh: the Stanford Armadillo (Stanford 3D Scanning Repository, research use)"
if [ ! -f "$mesh" ]; then
  mesh=$PWD/$OUT/blob.obj
  /usr/bin/python3 tools/scenes/make_blob_mesh.py "$mesh"
  note="mesh: femto's generated fallback creature (tools/scenes/make_blob_mesh.py); the Armadillo was not present"
fi
rows=""
if wants transient_path; then
  timed_render armadillo scenes/seed-glass-armadillo/scene.xml -D mesh="$mesh" \
    -D spp="$SPP" -D resolution="$RES" -D height=$((RES * 3 / 4)) "$@"
  rows="$rows|Dirac, transient_path=$OUT/armadillo.npy@5.5"
fi
if wants transient_beams; then
  timed_render beams_armadillo scenes/seed-glass-armadillo/scene.xml -D mesh="$mesh" -D integrator=transient_beams \
    -D resolution="$RES" -D height=$((RES * 3 / 4)) "$@"
  rows="$rows|Dirac, transient_beams=$OUT/beams_armadillo.npy@5.5"
fi
# Window: OPL 5.5 + 120 bins of 0.05: the floor lit directly from ~+1, light
# through the glass later, the back wall from ~+3.
IFS='|'
# shellcheck disable=SC2086  # split $rows on '|' into one argument per row
/usr/bin/python3 tools/figures/frame_strip.py "$OUT/fig4_glass_armadillo.png" ${rows#|} \
  --bin-width 0.05 --times 1.2 1.6 2.0 2.4 2.8 3.4 --average 3 --steady \
  --title "Seed fig. 4: glass figure (IOR 1.5) under a Dirac pulse; transient_path $SPP spp, transient_beams as in its integrator file" \
  --note "$note"
publish "$OUT/fig4_glass_armadillo.png"
# Animated with transient_beams (when rendered).
if wants transient_beams; then
  sequence_gif fig4_glass_armadillo_beams 2 0:60 "$OUT/beams_armadillo.npy"
fi
