#!/bin/sh
# One scene of the randomised media family (issue 14) measured beyond the CI
# runs' noise: seed K of tests/unit/integrators/transient_beams/
# media_scene_generator.h, RUNS runs of transient_beams (defaults, PASSES
# passes) and of transient_path (64 spp), compared as
# TransientBeamsRandomMedia does in CI (window sum and coarse bins, 5 sigma +
# the derived bias bound), with the closed form's window printed too.
# Seed 3 (camera and light inside a sphere), 64 runs x 4 passes: about 4 CPU
# minutes (docs/design/photon-beams.md, "A camera inside a medium").
#   tools/bench/random_media_seed.sh [K=3] [RUNS=64] [PASSES=4] [build dir=build]
set -eu
K=${1:-3}
RUNS=${2:-64}
PASSES=${3:-4}
BUILD=${4:-build}
FEMTO_MEDIA_SEED=$K FEMTO_MEDIA_RUNS=$RUNS FEMTO_MEDIA_PASSES=$PASSES FEMTO_PLUGIN_PATH="$BUILD/bin/plugins" \
  "$BUILD/bin/femto_unit_tests" --gtest_filter='TransientBeamsRandomMedia.*' 2>&1 | grep -E "^seed|^  |Failure|OK|FAILED"
