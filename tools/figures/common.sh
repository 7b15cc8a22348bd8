# Shared by the figure scripts (sourced): the femto program, the output
# folder, which integrators to render and a timed render that reports its
# wall time and the load (docs/GALLERY.md quotes these), and the copy of a
# figure for docs/images. Scripts set OUT_DEFAULT, SPP_DEFAULT and RES_DEFAULT
# first.
set -eu
FEMTO=${FEMTO:-build/bin/femto}
OUT=${OUT:-$OUT_DEFAULT}
SPP=${SPP:-$SPP_DEFAULT}
RES=${RES:-$RES_DEFAULT}
# Each figure renders with transient path tracing and with transient photon
# beams (whose budget is the scene's integrator-transient_beams.xml); e.g.
# INTEGRATORS=transient_beams renders only the beams part.
INTEGRATORS=${INTEGRATORS:-transient_path transient_beams}
# DOCS=docs/images: also write each figure there, smaller (publish below).
DOCS=${DOCS:-}
mkdir -p "$OUT"

# wants INTEGRATOR: is it one of $INTEGRATORS?
wants() {
  case " $INTEGRATORS " in *" $1 "*) return 0 ;; esac
  return 1
}

# timed_render NAME SCENE [femto render options...]: renders SCENE to $OUT/NAME.exr.
timed_render() {
  name=$1 scene=$2
  shift 2
  t0=$(date +%s)
  "$FEMTO" render "$scene" -o "$OUT/$name.exr" "$@"
  echo "$name: $(( $(date +%s) - t0 )) s wall (load average $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?'))"
}

# publish PNG: with DOCS set, writes a copy of PNG (a figure in $OUT) to
# $DOCS under the same name, scaled to 85 % and reduced to 256 colours, so a
# figure of four rows stays under ~400 KB in the repository (the renders'
# pixels are still larger than one of the figure's at that scale).
publish() {
  [ -n "$DOCS" ] || return 0
  mkdir -p "$DOCS"
  /usr/bin/python3 - "$1" "$DOCS/$(basename "$1")" <<'PY'
import sys
from PIL import Image  # matplotlib's own dependency
image = Image.open(sys.argv[1]).convert("RGB")
image = image.resize((image.width * 85 // 100, image.height * 85 // 100), Image.LANCZOS)
image.quantize(256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE).save(sys.argv[2], optimize=True)
print(f"wrote {sys.argv[2]}")
PY
}

# sequence_gif NAME MERGE FIRST:END [--each-exposure] VOLUME...: the volumes side by side
# (side_by_side_volume.py; each frame the mean of MERGE bins, so noise and
# file size stay down), frames FIRST..END-1 of that merged sequence as
# $OUT/NAME.gif through `femto frames --gif` (ffmpeg; one exposure for all;
# each frame stamped with its OPL when the volumes share one window).
# --each-exposure: each volume at its own exposure (side_by_side_volume.py).
# With DOCS set, a copy goes there when it is at most 1.5 MB.
sequence_gif() {
  name=$1 merge=$2 range=$3
  shift 3
  /usr/bin/python3 tools/figures/side_by_side_volume.py "$OUT/${name}_side_by_side.npy" "$@" --merge "$merge"
  # Time stamps when the volumes share one window (side_by_side_volume.py then writes a sidecar).
  label=
  [ -f "$OUT/${name}_side_by_side.json" ] && label=--label
  "$FEMTO" frames "$OUT/${name}_side_by_side.npy" -o "$OUT/${name}_frames" --bins "$range" --gif --fps 8 $label
  cp "$OUT/${name}_frames/sequence.gif" "$OUT/$name.gif"
  echo "wrote $OUT/$name.gif"
  [ -n "$DOCS" ] || return 0
  size=$(wc -c < "$OUT/$name.gif")
  if [ "$size" -le 1572864 ]; then
    cp "$OUT/$name.gif" "$DOCS/" && echo "wrote $DOCS/$name.gif"
  else
    echo "$OUT/$name.gif is $size bytes, over 1.5 MB: not copied to $DOCS" >&2
  fi
}
