#!/bin/sh
# The longer sweep of the randomised media scenes (issue 14): seeds 1..N of
# tests/unit/integrators/transient_beams/media_scene_generator.h, each
# rendered by transient_beams (defaults, derived radius) and transient_path,
# compared as TransientBeamsRandomMedia does in CI on seeds 1-3 (window sum
# and coarse bins within 5 sigma + the derived bias bound; nothing before
# the earliest arrival; no NaN/Inf), with 8 runs per renderer instead of
# CI's 4: on seed 23 four path runs read 12.35 +- 0.014 against the closed
# form's 12.298 (3.7 of their own standard errors: path's error at the
# sphere's silhouette is heavy-tailed and 4 runs underestimate its spread),
# which failed beams (-1.3 %) on a tolerance that 8 runs (path 12.304 +-
# 0.023, beams -1.07 %) keep. About 8 s of CPU per seed. The closed form
# averages 16 x 16 rays per pixel instead of CI's 8 x 8 (its error bound is
# the difference from 8 x 8): at 4 x 4 the sphere's silhouette across a
# pixel put seed 6's window 1.8 % high (2.6103 against 2.5635 at 64 x 64;
# path at 8 x 16384 spp: 2.5609 +- 0.0017). Both integrators are checked
# against it where the light is not near the view: with the light in view
# its pixel's 1/h singularity is underestimated even at 16 x 16 (seed 35:
# 9.40, 9.79, 9.86, 9.92 at 4, 16, 32, 64 rays a side; seeds 1 and 24 read
# 2-6 % below path at 16384 spp).
#   tools/bench/random_media_sweep.sh [N=40] [build dir=build]
set -eu
N=${1:-40}
BUILD=${2:-build}
FEMTO_MEDIA_CF_SUBPIXELS=${FEMTO_MEDIA_CF_SUBPIXELS:-16} FEMTO_MEDIA_RUNS=${FEMTO_MEDIA_RUNS:-8} FEMTO_MEDIA_SWEEP=$N FEMTO_PLUGIN_PATH="$BUILD/bin/plugins" \
  "$BUILD/bin/femto_unit_tests" --gtest_filter='TransientBeamsRandomMedia.*' 2>&1 | grep -E "^seed|window|Failure|OK|FAILED"
