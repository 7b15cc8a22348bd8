#pragma once
// The hook through which several processes share one render's tiles (MPI
// ranks launched by mpirun: tools/femto/mpi/). The core knows nothing of MPI:
// the program installs a TileDistribution for the length of a render and
// renderTileStream hands it the job. Determinism across processes needs
// nothing new: each pixel seeds its sampler from (seed, pixel index), so a
// tile's values do not depend on where it was rendered, and the consuming
// process still folds every tile in tile order (or, for tiles stored alone,
// TileJob::consumeWhereRendered, each process stores those it rendered).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <femto/loop/render_loop.h>

namespace femto {

class ProgressReporter;

/// One tile of a render: where it is, what it accumulated, its sample counts.
struct RenderTile {
  size_t index = 0;  // position in tile order (row-major over the crop window)
  Point2i offset, size;
  std::unique_ptr<TileAccumulator> accumulator;
  uint64_t samples = 0, invalid = 0;
};

/// What renderTileStream was asked to do.
struct TileJob {
  const Scene& scene;
  const RenderOptions& options;
  const TileFactory& makeTile;
  const TileConsumer& consume;
  ProgressReporter* progress;     // the bar of the whole job, advanced per pixel; null: the stream draws its own
  int tileSide;                   // of the tiles below (tileSideWithin: smaller with more threads for huge tiles)
  std::vector<RenderTile> tiles;  // every tile of the crop window, in tile order
  bool consumeWhereRendered = false;  // each process consumes its own tiles (renderTileStream)
};

/// The crop window's tiles of side `side` (tileSideWithin), in tile order
/// (accumulators not yet made).
std::vector<RenderTile> cropWindowTiles(const Scene& scene, int side);

/// Render the tiles `claim` hands out (null: no more) in parallel, with the
/// options' thread count, passing each finished tile to `deliver` serially
/// and in claim order. At most a few tiles per thread exist at once.
void renderClaimedTiles(const TileJob& job, const std::function<RenderTile*()>& claim,
                        const std::function<void(RenderTile&)>& deliver);

/// The warnings a finished tile stream logs (samples dropped, a cancel).
void reportTileStream(const RenderStats& stats);

class TileDistribution {
 public:
  virtual ~TileDistribution() = default;
  /// Render `job` across the processes. The consuming process calls
  /// job.consume for every rendered tile in tile order (after a cancel: the
  /// tiles begun, a prefix of that order); the others consume nothing. With
  /// job.consumeWhereRendered every process consumes the tiles it rendered
  /// (renderClaimedTiles does, as it renders them), and the job's stream ends
  /// on every process only after all have consumed theirs. Every process returns the
  /// statistics of the whole job.
  virtual RenderStats run(TileJob& job) = 0;
  /// This process's rank among ranks() (for work split by index, as photon
  /// passes are: every rank traces its share and gatherAll exchanges them).
  virtual int rank() const { return 0; }
  virtual int ranks() const { return 1; }
  /// Every rank's `mine`, concatenated in rank order. A collective: every
  /// rank calls it, in the same order, from the thread that renders.
  virtual std::vector<char> gatherAll(const std::vector<char>& mine) { return mine; }
};

/// Installs `distribution` (not owned; null: every tile renders in this
/// process, the default) for the renders that follow.
void setTileDistribution(TileDistribution* distribution);
TileDistribution* tileDistribution();

}  // namespace femto
