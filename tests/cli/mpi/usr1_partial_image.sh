#!/usr/bin/env bash
# SIGUSR1 to mpirun (forwarded to every rank) acts as a first Ctrl-C on one
# process: rank 0 hands out no more tiles, the tiles handed out are finished
# and a valid partial image is written; the job exits with 130.
#   usr1_partial_image.sh FEMTO SCENE OUT_DIR [render options...]
set -u
femto=$1 scene=$2 out=$3
shift 3
. "$(dirname "$0")/mpi_env.sh"
rm -rf "$out" && mkdir -p "$out"
image=$out/partial.exr
"${mpirun_cmd[@]}" -n 2 "$femto" render "$scene" -o "$image" --no-progress "$@" >"$out/job.log" 2>&1 &
job=$!
# Wait until rank 0 catches SIGUSR1 (bit 10 of SigCgt): it installs its
# handlers just before rendering.
rank0=""
for _ in $(seq 600); do
  for pid in $(pgrep -P "$job" femto); do
    tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=0" && rank0=$pid
  done
  if [ -n "$rank0" ]; then
    mask=$(awk '/^SigCgt:/ {print $2}' "/proc/$rank0/status" 2>/dev/null)
    [ -n "$mask" ] && (( (16#$mask & (1 << 9)) != 0 )) && break
  fi
  kill -0 "$job" 2>/dev/null || { echo "the job ended before rendering"; cat "$out/job.log"; exit 1; }
  sleep 0.1
done
sleep 1
kill -USR1 "$job"
for _ in $(seq 900); do
  kill -0 "$job" 2>/dev/null || break
  sleep 0.1
done
if kill -0 "$job" 2>/dev/null; then
  kill -KILL "$job"; echo "the job did not stop within 90 s of SIGUSR1"; cat "$out/job.log"; exit 1
fi
wait "$job"; code=$?
cat "$out/job.log"
[ "$code" -eq 130 ] || { echo "expected exit 130 (a partial image), got $code"; exit 1; }
[ -s "$image" ] || { echo "no partial image at $image"; exit 1; }
grep -q "^stopped early, partial image" "$out/job.log" || { echo "no partial-image summary"; exit 1; }
echo "partial image written: $image"
