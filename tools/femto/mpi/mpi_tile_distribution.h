#pragma once
// Tiles shared between MPI ranks, dynamically: rank 0 hands out tile indices
// in tile order to whichever rank asks (itself included) and each rank
// renders its tiles with its own threads. Each pixel's sampler is seeded from
// (seed, pixel index), so where a tile was rendered changes nothing: the
// output is bitwise that of one process, whatever the rank and thread counts.
// Where a pixel's stored value depends on its tile alone (transient films
// without a filter border: TileJob::consumeWhereRendered), each rank stores
// the tiles it rendered itself (positioned writes into rank 0's volume,
// transient_output.h) and sends rank 0 only their sample counts; otherwise
// it sends the raw sums and rank 0 folds every tile in tile order, as one
// process would.
//
// Messages (MPI_COMM_WORLD, only the main thread of each rank calls MPI):
//   worker -> 0  Request   one uint64: how many more tiles it wants (when it
//                          has no finished tile to send the request with)
//   0 -> worker  Assign    uint64 tile indices, in order; none: no more
//   worker -> 0  TileData  how many more tiles it wants (0: none), then a
//                          header (index, samples, invalid) per finished tile,
//                          then the packed sums of the one tile unless the
//                          worker stored its tiles itself
// and at the end of each stream a broadcast of the job's statistics, so every
// rank stops (a cancel) or goes on to the next pass together.
#include <mpi.h>

#include <femto/loop/tile_distribution.h>

namespace femto::cli {

class MpiTileDistribution final : public TileDistribution {
 public:
  explicit MpiTileDistribution(MPI_Comm comm);
  RenderStats run(TileJob& job) override;
  int rank() const override { return rank_; }
  int ranks() const override { return size_; }
  std::vector<char> gatherAll(const std::vector<char>& mine) override;

 private:
  RenderStats coordinate(TileJob& job);
  void work(TileJob& job);
  RenderStats shareStats(const RenderStats& stats);
  /// MPI_Allreduce of one int, waited for sleeping (mpi_wait.h).
  void allreduceSleeping(int* value, MPI_Op op);
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

}  // namespace femto::cli
