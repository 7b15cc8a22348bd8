// RenderProcesses with MPI: the ranks of the job mpirun (or srun) started.
#include <mpi.h>

#include <cstdlib>
#include <iostream>
#include <memory>

#include <femto/base/error.h>
#include <femto/core/log.h>

#include "mpi_tile_distribution.h"
#include "mpi_wait.h"
#include "render_processes.h"

namespace femto::cli {
namespace {

/// Did an MPI launcher start this process? Open MPI's mpirun sets
/// OMPI_COMM_WORLD_SIZE, PMIx launchers (srun --mpi=pmix) PMIX_RANK, PMI-1/2
/// ones PMI_SIZE. Without one, MPI_Init would start a singleton runtime for nothing.
bool launchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (std::getenv(name)) return true;
  return false;
}

std::unique_ptr<MpiTileDistribution> gDistribution;

}  // namespace

RenderProcesses::RenderProcesses() {
  if (!launchedByMpi()) return;
  // Only the main thread of a rank calls MPI (the tiles render on others).
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw Error("cannot join the MPI job (MPI_Init_thread failed)");
  joined_ = true;
  // Errors end the job with a message rather than with a return code nobody checks.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &count_);
  if (provided < MPI_THREAD_FUNNELED) abortJob("the MPI library does not allow threads (MPI_THREAD_FUNNELED)");
  if (count_ == 1) return;  // one rank: the ordinary render
  gDistribution = std::make_unique<MpiTileDistribution>(MPI_COMM_WORLD);
  setTileDistribution(gDistribution.get());
  // The other ranks' warnings would repeat rank 0's.
  ownLogLevel_ = int(logLevel());
  if (!writes()) setLogLevel(LogLevel::Error);
}

RenderProcesses::~RenderProcesses() {
  if (!joined_) return;
  setTileDistribution(nullptr);
  gDistribution.reset();
  // The other ranks wait here while rank 0 writes the outputs: sleeping, not
  // in MPI_Finalize (which would spin).
  MPI_Request barrier;
  MPI_Ibarrier(MPI_COMM_WORLD, &barrier);
  waitSleeping(barrier);
  MPI_Finalize();
}

void RenderProcesses::shareTiles(bool share) {
  sharing_ = share;
  if (count_ == 1) return;
  setTileDistribution(share ? gDistribution.get() : nullptr);
  // A rank rendering scenes of its own reports them as rank 0 does.
  setLogLevel(share && rank_ != 0 ? LogLevel::Error : LogLevel(ownLogLevel_));
}

void RenderProcesses::abortJob(const std::string& message) const {
  // One write, so that mpirun does not splice other ranks' output into the line.
  std::cerr << str("error: ", count_ > 1 ? str("rank ", rank_, " of ", count_, ": ") : std::string(), message, '\n') << std::flush;
  if (joined_) MPI_Abort(MPI_COMM_WORLD, 1);
  std::exit(1);
}

}  // namespace femto::cli
