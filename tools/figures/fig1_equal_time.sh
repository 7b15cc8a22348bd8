#!/bin/sh
# Seed figure 1: equal-time comparison on the fog Cornell box
# (scenes/cornell-box-fog): transient path tracing vs transient photon beams
# at the same time (CPU or wall clock), frames side by side with a long reference, and
# each one's error against it in the caption.
#   out/fig1/fig1_equal_time.png   frames (rows: path, beams, reference) + steady column
#   out/fig1/fig1_equal_time.gif   the three sequences side by side
#   out/fig1/equal_time.json       times, budgets, errors (tools/figures/equal_time.py)
# With DOCS=docs/images, also the PNG (smaller: common.sh's publish) and the GIF there.
# transient_beams renders PASSES passes; transient_path then renders the spp
# that take the same time (a pilot at SPP spp, then up to four renders, each
# guess corrected by the last two: tools/figures/equal_time.py). The reference is the mean of
# REF_RUNS transient_path renders of REF_SPP spp with other seeds, cached
# under build/compare-cache (tools/compare/reference_volume.py: its spread
# also estimates the reference's own error, which the caption gives and
# subtracts). The first run renders it: ~30 min on 2 busy cores.
# Usage (from the repository root, after building femto and its plugins):
#   tools/figures/fig1_equal_time.sh [-D NAME=VALUE ...]   (scene overrides for every render)
# Environment: FEMTO (build/bin/femto), OUT (out/fig1), SPP (pilot spp, 16),
# RES (128), PASSES (16), BINS (512, a multiple of 64, over the scene's window OPL 3 to 13.24),
# REF_SPP (2048), REF_RUNS (8), THREADS (0: all cores), EQUAL (what is made
# equal: cpu_seconds, the femto processes' CPU times, the default; seconds, the
# render times femto reports, wall clock). Both are measured and printed. On
# the shared build machine the path tracer's wall time at a fixed spp varied
# by +-25 % between renders a minute apart (load 4-15), its CPU time by ~3 %,
# so wall-clock matching missed 10 % in two of three runs (docs/GALLERY.md);
# on an idle machine use EQUAL=seconds.
OUT_DEFAULT=out/fig1 SPP_DEFAULT=16 RES_DEFAULT=128
. tools/figures/common.sh
. tools/bench/provenance.sh
PASSES=${PASSES:-16}
BINS=${BINS:-512}
if [ $((BINS % 64)) -ne 0 ]; then
  echo "fig1_equal_time.sh: BINS=$BINS must be a multiple of 64 (the GIF's frames merge BINS/64 bins)" >&2
  exit 1
fi
BIN_WIDTH=$(awk "BEGIN { print 10.24 / $BINS }")
REF_SPP=${REF_SPP:-2048}
REF_RUNS=${REF_RUNS:-8}
THREADS=${THREADS:-0}
EQUAL=${EQUAL:-cpu_seconds}
SCENE=scenes/cornell-box-fog/scene.xml

load_before=$(cut -d' ' -f1-3 /proc/loadavg)
/usr/bin/python3 tools/figures/equal_time.py "$SCENE" --out "$OUT" --femto "$FEMTO" --threads "$THREADS" \
  --passes "$PASSES" --pilot-spp "$SPP" --time "$EQUAL" --reference-spp "$REF_SPP" --reference-runs "$REF_RUNS" \
  -D resolution="$RES" -D bins="$BINS" -D bin_width="$BIN_WIDTH" -D frames=false "$@"
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

# field EXPR: a value of equal_time.json (d); captions are written there.
field() { /usr/bin/python3 -c "import json; d = json.load(open('$OUT/equal_time.json')); print($1)"; }
reference=$(field "d['reference']['file']")
threads=$THREADS
[ "$threads" -gt 0 ] || threads=$(nproc)
machine="$model, $threads threads; commit $commit$dirty; load average $load_before before, $load_after after"
echo "$machine"

# Columns: the direct wavefront crossing the fog (+1.1, +1.4), reaching the
# ceiling, walls and box tops (+1.8, +2.3), the back wall as a ring (+3.0),
# then indirect light and multiple scattering (+4.0); the window starts at OPL 3.
/usr/bin/python3 tools/figures/frame_strip.py "$OUT/fig1_equal_time.png" \
  "$(field "d['captions']['path']")=$OUT/path.npy@3" "$(field "d['captions']['beams']")=$OUT/beams.npy@3" \
  "$(field "d['captions']['reference']")=$reference@3" \
  --bin-width "$BIN_WIDTH" --times 1.1 1.4 1.8 2.3 3.0 4.0 --average 3 --steady \
  --title "Seed fig. 1: fog Cornell box, ${RES}x$RES, $BINS bins of OPL $BIN_WIDTH, path tracing and photon beams at equal time" \
  --note "$(field "d['captions']['note']")
$machine"
publish "$OUT/fig1_equal_time.png"

# The GIF: path | beams | reference, each frame the mean of BINS/64 bins
# (OPL 0.16), from +0.96 to +6.08 after the window start (32 frames; the
# path tracer's noise makes every frame expensive to store).
sequence_gif fig1_equal_time $((BINS / 64)) 6:38 "$OUT/path.npy" "$OUT/beams.npy" "$reference"
