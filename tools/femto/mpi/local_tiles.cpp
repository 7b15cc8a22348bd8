#include "local_tiles.h"

#include <tbb/task_arena.h>

namespace femto::cli {

int LocalTiles::threadsOf(const TileJob& job) {
  return job.options.threads > 0 ? job.options.threads : tbb::this_task_arena::max_concurrency();
}

LocalTiles::LocalTiles(const TileJob& job) {
  const int threads = threadsOf(job);
  // The pipeline holds two tiles per thread; two more queued hide the time
  // an assignment takes to arrive from rank 0.
  wanted_ = size_t(2 * threads + 2);
  thread_ = std::thread([this, &job] { render(job); });
}

LocalTiles::~LocalTiles() {
  close();
  thread_.join();
}

void LocalTiles::render(const TileJob& job) {
  auto claim = [&]() -> RenderTile* {
    std::unique_lock lock(mutex_);
    assigned_.wait(lock, [&] { return !queue_.empty() || closed_; });
    if (queue_.empty()) return nullptr;
    RenderTile* tile = queue_.front();
    queue_.pop_front();
    return tile;
  };
  auto deliver = [&](RenderTile& tile) {
    std::lock_guard lock(mutex_);
    done_.push_back(&tile);
    finished_.notify_one();
  };
  try {
    renderClaimedTiles(job, claim, deliver);
  } catch (...) {
    std::lock_guard lock(mutex_);
    error_ = std::current_exception();
  }
  std::lock_guard lock(mutex_);
  stopped_ = true;
  finished_.notify_one();
}

void LocalTiles::assign(RenderTile* tile) {
  std::lock_guard lock(mutex_);
  queue_.push_back(tile);
  ++pending_;
  assigned_.notify_one();
}

void LocalTiles::close() {
  std::lock_guard lock(mutex_);
  closed_ = true;
  assigned_.notify_one();
}

size_t LocalTiles::pending() const {
  std::lock_guard lock(mutex_);
  return pending_;
}

std::vector<RenderTile*> LocalTiles::takeFinished() {
  std::lock_guard lock(mutex_);
  if (error_) std::rethrow_exception(error_);
  std::vector<RenderTile*> tiles;
  tiles.swap(done_);
  pending_ -= tiles.size();
  return tiles;
}

bool LocalTiles::done() const {
  std::lock_guard lock(mutex_);
  return closed_ && stopped_ && done_.empty() && !error_;
}

void LocalTiles::waitForFinished(std::chrono::microseconds timeout) {
  std::unique_lock lock(mutex_);
  finished_.wait_for(lock, timeout, [&] { return !done_.empty() || error_; });
}

}  // namespace femto::cli
