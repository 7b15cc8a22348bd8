#pragma once
// This process's share of a distributed render's tiles, rendered by the
// usual tile pipeline (renderClaimedTiles) on a thread of its own, so the
// main thread stays free to talk MPI (the only thread that does: MPI is
// initialised with MPI_THREAD_FUNNELED). The main thread assigns tiles and
// collects the finished ones; the render thread waits when it has none.
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <femto/loop/tile_distribution.h>

namespace femto::cli {

class LocalTiles {
 public:
  explicit LocalTiles(const TileJob& job);
  /// Waits for the render thread (after close(), or it renders forever).
  ~LocalTiles();
  LocalTiles(const LocalTiles&) = delete;
  LocalTiles& operator=(const LocalTiles&) = delete;

  /// One more tile to render here.
  void assign(RenderTile* tile);
  /// No more tiles will be assigned.
  void close();
  /// Tiles assigned and not yet taken back by takeFinished.
  size_t pending() const;
  /// The tiles finished since the last call, in assignment order. Rethrows
  /// what the render thread threw.
  std::vector<RenderTile*> takeFinished();
  /// Closed, rendered, and every finished tile taken.
  bool done() const;
  /// Sleeps until a tile finishes or `timeout` passes.
  void waitForFinished(std::chrono::microseconds timeout);
  /// The threads `job` renders with in this process.
  static int threadsOf(const TileJob& job);
  /// Tiles worth keeping assigned to keep every thread of this process busy.
  size_t wanted() const { return wanted_; }

 private:
  void render(const TileJob& job);
  mutable std::mutex mutex_;
  std::condition_variable assigned_, finished_;
  std::deque<RenderTile*> queue_;
  std::vector<RenderTile*> done_;
  size_t pending_ = 0, wanted_ = 0;
  bool closed_ = false, stopped_ = false;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace femto::cli
