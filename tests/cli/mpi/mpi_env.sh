# Sourced by the MPI tests: how they start mpirun. Loopback only (shared
# memory between the ranks, the launcher's own channel on lo), more ranks
# than cores allowed, and as root when the tests run as root (containers).
mpirun_cmd=(mpirun --oversubscribe --mca btl self,vader --mca oob_tcp_if_include lo)
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
