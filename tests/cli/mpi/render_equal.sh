#!/usr/bin/env bash
# `mpirun -n N femto render` must write the same bits as one process, for
# every rank and thread count: every file of the render (image, previews,
# volume, sidecar, frames) is compared byte for byte with a plain render.
#   render_equal.sh FEMTO SCENE OUT_DIR "RANKSxTHREADS ..." [render options...]
# With STORED=own (or rank0) in the environment, the log must also say that
# each rank stored its own tiles (or that it did not: rank 0 stored them).
set -u
femto=$1 scene=$2 out=$3 runs=${4//;/ }  # "2x1 3x2" or a CMake list "2x1;3x2"
shift 4
. "$(dirname "$0")/mpi_env.sh"
rm -rf "$out" && mkdir -p "$out"
"$femto" render "$scene" -o "$out/one/out.exr" -t 2 --no-progress "$@" >"$out/one.log" 2>&1 ||
  { cat "$out/one.log"; echo "the single-process render failed"; exit 1; }
files=$(cd "$out/one" && find . -type f | sort)
status=0
for run in $runs; do
  ranks=${run%x*} threads=${run#*x}
  dir=$out/n${ranks}_t${threads}
  # The test means something only if every rank rendered tiles: the scene
  # must have more tiles than rank 0 takes first (2 x threads + 2). On a
  # loaded machine a rank that starts late may find none left: that run is
  # made again (at most 3 times; the bits are compared on the last).
  for attempt in 1 2 3; do
    rm -rf "$dir"
    FEMTO_LOG_LEVEL=debug "${mpirun_cmd[@]}" -x FEMTO_LOG_LEVEL -n "$ranks" "$femto" render "$scene" -o "$dir/out.exr" -t "$threads" --no-progress "$@" \
      >"$dir.log" 2>&1
    rc=$?
    [ $rc -eq 0 ] || break
    [ "$ranks" -gt 1 ] && grep -E "tiles rendered by ranks" "$dir.log" | grep -qE ":( [0-9]+)* 0( |;|$)" || break
    [ $attempt -lt 3 ] && echo "n=$ranks t=$threads: a rank rendered no tiles (attempt $attempt); again"
  done
  if [ $rc -ne 0 ]; then
    cat "$dir.log"; echo "mpirun -n $ranks with $threads threads failed"; status=1; continue
  fi
  before=$status status=0
  got=$(cd "$dir" && find . -type f | sort)
  [ "$got" = "$files" ] || { echo "n=$ranks t=$threads wrote other files:"; diff <(echo "$files") <(echo "$got"); status=1; }
  for f in $files; do
    cmp -s "$out/one/$f" "$dir/$f" || { echo "n=$ranks t=$threads: $f differs from one process"; status=1; }
  done
  [ "$(grep -c '^rendered ' "$dir.log")" -eq 1 ] || { echo "n=$ranks: expected one summary line"; cat "$dir.log"; status=1; }
  if [ "$ranks" -gt 1 ] && [ -n "${STORED:-}" ]; then
    own=$(grep -c "tiles rendered by ranks.*each rank stored its own tiles" "$dir.log")
    all=$(grep -c "tiles rendered by ranks" "$dir.log")
    { [ "$STORED" = own ] && [ "$own" -eq "$all" ]; } || { [ "$STORED" = rank0 ] && [ "$own" -eq 0 ]; } ||
      { echo "n=$ranks t=$threads: expected tiles stored by $STORED ($own of $all streams stored by their ranks)"; status=1; }
  fi
  if [ "$ranks" -gt 1 ]; then
    grep -E "tiles rendered by ranks" "$dir.log" | grep -qE ":( [0-9]+)* 0( |;|$)" &&
      { echo "n=$ranks t=$threads: a rank rendered no tiles:"; grep "tiles rendered" "$dir.log"; status=1; }
  fi
  [ $status -eq 0 ] && echo "n=$ranks t=$threads: $(echo "$files" | wc -l) files identical ($(grep -m1 -o 'tiles rendered.*' "$dir.log"))"
  [ $before -eq 0 ] || status=1
done
exit $status
