#!/usr/bin/env bash
# SIGUSR1 to mpirun (forwarded to every rank) acts as a first Ctrl-C on one
# process: rank 0 hands out no more tiles, the tiles handed out are finished
# and a valid partial image is written; the job exits with 130.
#   usr1_partial_image.sh FEMTO SCENE OUT_DIR [render options...]
set -u
femto=$1 scene=$2 out=$3
shift 3
. "$(dirname "$0")/mpi_env.sh"
. "$(dirname "$0")/../process_wait.sh"
rm -rf "$out" && mkdir -p "$out"
image=$out/partial.exr
"${mpirun_cmd[@]}" -n 2 "$femto" render "$scene" -o "$image" --no-progress "$@" >"$out/job.log" 2>&1 &
job=$!
# Rank 0 installs its handlers just before rendering.
wait_for_handler 10 "$job" 0 >/dev/null || { echo "rank 0 never started rendering"; cat "$out/job.log"; exit 1; }
sleep 1
kill -USR1 "$job"
wait_for_exit "$job" 90 || { echo "the job did not stop within 90 s of SIGUSR1"; cat "$out/job.log"; exit 1; }
wait "$job"; code=$?
cat "$out/job.log"
[ "$code" -eq 130 ] || { echo "expected exit 130 (a partial image), got $code"; exit 1; }
[ -s "$image" ] || { echo "no partial image at $image"; exit 1; }
grep -q "^stopped early, partial image" "$out/job.log" || { echo "no partial-image summary"; exit 1; }
# A transient film's volume too: complete in size (every rank's rows at their offsets) and readable.
if [ -e "${image%.exr}.npy" ]; then
  /usr/bin/python3 -c "import numpy, sys; v = numpy.load(sys.argv[1]); assert v.ndim == 4 and numpy.isfinite(v).all() and v.any()" \
    "${image%.exr}.npy" || { echo "the partial volume does not read, or is empty"; exit 1; }
  left=$(cd "$out" && ls -A | grep "^\.tmp-")
  [ -z "$left" ] || { echo "temporaries left behind: $left"; exit 1; }
fi
echo "partial image written: $image"
