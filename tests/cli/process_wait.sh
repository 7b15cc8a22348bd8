# Sourced by the signal tests (interrupt_render.sh, mpi/kill_rank.sh,
# mpi/usr1_partial_image.sh): waiting for a femto process to be ready for a
# signal, and for it to end, without sleeping a fixed time.

# Does PID catch signal SIGNUM? Bit SIGNUM-1 of SigCgt in /proc/PID/status:
# femto installs its handlers once the scene is loaded, just before rendering.
catches_signal() {
  local mask
  mask=$(awk '/^SigCgt:/ {print $2}' "/proc/$1/status" 2>/dev/null) || return 1
  [ -n "$mask" ] && (( (16#$mask & (1 << ($2 - 1))) != 0 ))
}

# The femto child of mpirun JOB whose environment names it rank RANK (empty
# when it has not started).
rank_pid() {
  local pid
  for pid in $(pgrep -P "$1" femto); do
    tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2" && { echo "$pid"; return; }
  done
}

# wait_for_handler SIGNUM JOB [RANK]: prints the pid of JOB (or of its rank
# RANK under mpirun) once it catches SIGNUM, within 60 s. Fails, printing
# nothing, when JOB ends first or the time runs out.
wait_for_handler() {
  local signum=$1 job=$2 rank=${3:-} target
  for _ in $(seq 600); do
    if [ -n "$rank" ]; then target=$(rank_pid "$job" "$rank"); else target=$job; fi
    [ -n "$target" ] && catches_signal "$target" "$signum" && { echo "$target"; return 0; }
    kill -0 "$job" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}

# wait_for_exit PID SECONDS: succeeds once PID has ended; after SECONDS it
# kills PID and fails (a stop that hangs is a test failure, not a hung test).
wait_for_exit() {
  for _ in $(seq $(($2 * 10))); do
    kill -0 "$1" 2>/dev/null || return 0
    sleep 0.1
  done
  kill -KILL "$1" 2>/dev/null
  return 1
}
