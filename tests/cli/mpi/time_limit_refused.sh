#!/usr/bin/env bash
# Under mpirun, --time-limit is refused before any work (the ranks would have
# to agree pass by pass on the time left), once, naming --passes instead.
#   time_limit_refused.sh FEMTO SCENE OUT_DIR [render options...]
set -u
femto=$1 scene=$2 out=$3
shift 3
. "$(dirname "$0")/mpi_env.sh"
rm -rf "$out" && mkdir -p "$out"
"${mpirun_cmd[@]}" -n 2 "$femto" render "$scene" -o "$out/out.exr" --no-progress --time-limit 5s "$@" >"$out/log" 2>&1
code=$?
status=0
[ $code -ne 0 ] || { echo "mpirun with --time-limit exited 0"; status=1; }
[ "$(grep -c 'error: --time-limit is not supported under mpirun (2 ranks): give the number of passes instead (--passes N' "$out/log")" -eq 1 ] ||
  { echo "expected the refusal once:"; status=1; }
[ ! -e "$out/out.exr" ] || { echo "a refused render wrote $out/out.exr"; status=1; }
cat "$out/log"
exit $status
