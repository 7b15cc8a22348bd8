#!/usr/bin/env bash
# A rank that dies mid-render ends the whole job: mpirun exits non-zero,
# names the rank, and no output appears under the final names (outputs are
# written under temporary names and renamed only at the end); mpirun ends
# rank 0 with SIGTERM, on which femto removes those temporaries too.
#   kill_rank.sh FEMTO SCENE OUT_DIR [render options...]
set -u
femto=$1 scene=$2 out=$3
shift 3
. "$(dirname "$0")/mpi_env.sh"
. "$(dirname "$0")/../process_wait.sh"
rm -rf "$out" && mkdir -p "$out"
# Minutes of work, so the job is surely still rendering when rank 1 dies.
"${mpirun_cmd[@]}" -n 2 "$femto" render "$scene" -o "$out/killed.exr" --no-progress "$@" >"$out/job.log" 2>&1 &
job=$!
# Rank 1 installs its Ctrl-C handler just before rendering.
rank1=$(wait_for_handler 2 "$job" 1) || { kill -KILL "$job"; echo "rank 1 never started rendering"; cat "$out/job.log"; exit 1; }
sleep 1
kill -KILL "$rank1"
wait_for_exit "$job" 60 || { echo "the job did not end within 60 s of rank 1's death"; cat "$out/job.log"; exit 1; }
wait "$job"; code=$?
cat "$out/job.log"
[ "$code" -ne 0 ] || { echo "expected a non-zero exit after a rank died"; exit 1; }
grep -q "rank 1" "$out/job.log" || { echo "the message does not name the rank that died"; exit 1; }
left=$(cd "$out" && ls -A | grep -vx job.log)
[ -z "$left" ] || { echo "files left behind: $left"; exit 1; }
echo "exit $code, nothing written"
