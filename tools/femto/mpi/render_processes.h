#pragma once
// The processes one `femto render` runs as: one, or the ranks mpirun (or
// srun) launched, which then share the render's tiles (mpi_tile_distribution.h).
// Built without MPI (single_process.cpp), or launched without mpirun, there
// is one process and nothing changes.
#include <string>

namespace femto::cli {

class RenderProcesses {
 public:
  /// Joins the MPI job when the launcher's environment says there is one
  /// (never initialises MPI otherwise: a plain `femto render` starts no MPI
  /// runtime) and installs the tile distribution for the renders that follow.
  RenderProcesses();
  ~RenderProcesses();
  RenderProcesses(const RenderProcesses&) = delete;
  RenderProcesses& operator=(const RenderProcesses&) = delete;

  int rank() const { return rank_; }
  int count() const { return count_; }
  /// Only rank 0 writes files, prints the summary and draws the progress bar
  /// (unless the ranks render scenes of their own: shareTiles(false)).
  bool writes() const { return rank_ == 0 || !sharing_; }
  /// Whether the ranks share each render's tiles (the default) or each
  /// renders whole scenes alone (false: more scenes than ranks).
  void shareTiles(bool share);
  bool sharesTiles() const { return sharing_ && count_ > 1; }
  /// A failure on one rank ends every rank (the others would wait for it):
  /// prints `message` naming the rank and aborts the job with exit code 1.
  [[noreturn]] void abortJob(const std::string& message) const;

 private:
  int rank_ = 0, count_ = 1;
  bool joined_ = false;
  bool sharing_ = true;
  int ownLogLevel_ = 1;  // the log level before a sharing rank's is lowered (femto::LogLevel)
};

}  // namespace femto::cli
