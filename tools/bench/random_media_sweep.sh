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
# 0.023, beams -1.07 %) keep. About 8 s of CPU per seed.
#   tools/bench/random_media_sweep.sh [N=40] [build dir=build]
set -eu
N=${1:-40}
BUILD=${2:-build}
FEMTO_MEDIA_RUNS=${FEMTO_MEDIA_RUNS:-8} FEMTO_MEDIA_SWEEP=$N FEMTO_PLUGIN_PATH="$BUILD/bin/plugins" \
  "$BUILD/bin/femto_unit_tests" --gtest_filter='TransientBeamsRandomMedia.*' 2>&1 | grep -E "^seed|window|Failure|OK|FAILED"
