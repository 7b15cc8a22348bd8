# Shared by the figure scripts (sourced): the femto program, the output
# folder and a timed render that reports its wall time (docs/GALLERY.md
# quotes these). Scripts set OUT_DEFAULT, SPP_DEFAULT and RES_DEFAULT first.
set -eu
FEMTO=${FEMTO:-build/bin/femto}
OUT=${OUT:-$OUT_DEFAULT}
SPP=${SPP:-$SPP_DEFAULT}
RES=${RES:-$RES_DEFAULT}
mkdir -p "$OUT"

# timed_render NAME SCENE [femto render options...]: renders SCENE to $OUT/NAME.exr.
timed_render() {
  name=$1 scene=$2
  shift 2
  t0=$(date +%s)
  "$FEMTO" render "$scene" -o "$OUT/$name.exr" "$@"
  echo "$name: $(( $(date +%s) - t0 )) s wall"
}
