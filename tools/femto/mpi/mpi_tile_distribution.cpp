#include "mpi_tile_distribution.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <limits>
#include <optional>
#include <vector>

#include <femto/core/log.h>
#include <femto/core/progress.h>
#include <femto/render/scene.h>

#include "local_tiles.h"
#include "mpi_wait.h"

namespace femto::cli {
namespace {

enum Tag : int { Request = 1, Assign = 2, TileData = 3 };

/// A TileData message: how many more tiles the sender wants (a request
/// riding along; 0: none), then `tiles` headers, then the packed sums of the
/// one tile when it was not stored where rendered.
struct MessageHead {
  uint64_t more, tiles;
};
struct TileHeader {
  uint64_t index, samples, invalid;
};
static_assert(sizeof(MessageHead) % sizeof(float) == 0 && sizeof(TileHeader) % sizeof(float) == 0);

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw Error(str("MPI ", what, " failed (error ", code, ")"));
}

}  // namespace

MpiTileDistribution::MpiTileDistribution(MPI_Comm comm) : comm_(comm) {
  MPI_Comm_rank(comm_, &rank_);
  MPI_Comm_size(comm_, &size_);
}

RenderStats MpiTileDistribution::run(TileJob& job) {
  // Every rank must cut the same tiles: the side shrinks with a rank's thread
  // count when tiles are huge (tileSideWithin), so take the smallest, which
  // fits every rank's memory bound.
  int side = job.tileSide;
  allreduceSleeping(&side, MPI_MIN);
  // Each rank keeps a few tiles queued (LocalTiles::wanted), so the last
  // ones may wait on one rank while another has none: cut tiles small
  // enough that every thread of the job gets many (at least 64 tiles a
  // thread, or 4-pixel tiles). Only where each tile's pixels are stored
  // alone: filters' borders are summed in tile order, which the side changes.
  if (job.consumeWhereRendered) {
    int threads = LocalTiles::threadsOf(job);
    allreduceSleeping(&threads, MPI_SUM);
    const Point2i crop = job.scene.sensor().film().cropSize();
    const double balanced = std::sqrt(double(crop.x) * double(crop.y) / (64.0 * threads));
    side = std::clamp(int(balanced), std::min(side, 4), side);
  }
  if (side != job.tileSide) job.tiles = cropWindowTiles(job.scene, side), job.tileSide = side;
  if (rank_ == 0) return shareStats(coordinate(job));
  work(job);
  return shareStats(RenderStats());
}

void MpiTileDistribution::allreduceSleeping(int* value, MPI_Op op) {
  MPI_Request request;
  check(MPI_Iallreduce(MPI_IN_PLACE, value, 1, MPI_INT, op, comm_, &request), "reduce");
  waitSleeping(request);
}

RenderStats MpiTileDistribution::shareStats(const RenderStats& stats) {
  // Rank 0's statistics are the job's; the others learn from them whether
  // the stream completed (after a cancel every rank stops together).
  uint64_t counts[3] = {stats.completed ? 1u : 0u, stats.samples, stats.invalidSamples};
  double seconds = stats.seconds;
  // Non-blocking and waited for sleeping: the other ranks wait here while
  // rank 0 folds its last tiles.
  MPI_Request requests[2];
  check(MPI_Ibcast(counts, 3, MPI_UINT64_T, 0, comm_, &requests[0]), "broadcast");
  check(MPI_Ibcast(&seconds, 1, MPI_DOUBLE, 0, comm_, &requests[1]), "broadcast");
  for (MPI_Request& request : requests) waitSleeping(request);
  RenderStats shared;
  shared.completed = counts[0] != 0;
  shared.samples = counts[1], shared.invalidSamples = counts[2];
  shared.seconds = seconds;
  return shared;
}

RenderStats MpiTileDistribution::coordinate(TileJob& job) {
  // The job's bar when the stream is part of a longer job (passes, frames), else one of its own.
  const Point2i crop = job.scene.sensor().film().cropSize();
  std::optional<ProgressReporter> ownProgress;
  ProgressReporter& progress =
      job.progress ? *job.progress
                   : ownProgress.emplace("Rendering", uint64_t(crop.x) * uint64_t(crop.y), job.options.progress);
  const auto start = std::chrono::steady_clock::now();
  std::vector<RenderTile>& tiles = job.tiles;
  size_t next = 0, consumed = 0;
  bool cancelled = false;
  int workersOpen = size_ - 1;
  RenderStats stats;
  // Tile indices in tile order, to whoever asks: after a cancel none, so the
  // tiles handed out, and hence consumed, are a prefix of the tile order.
  auto handOut = [&](uint64_t count) {
    std::vector<uint64_t> ids;
    if (!cancelled && job.options.cancel && job.options.cancel->load(std::memory_order_relaxed)) cancelled = true;
    while (!cancelled && next < tiles.size() && ids.size() < count) ids.push_back(next++);
    return ids;
  };
  // Set by the main thread only when a tile is finished (a tile rendering
  // here already has its accumulator, so that cannot tell).
  std::vector<bool> ready(tiles.size(), false);
  auto arrived = [&](RenderTile& tile) {
    ready[tile.index] = true;
    progress.update(uint64_t(tile.size.x) * uint64_t(tile.size.y));
  };

  std::vector<size_t> perRank(size_t(size_), 0);  // tiles handed to each rank, for the log
  uint64_t bytesReceived = 0, tilesReceived = 0;
  double coordinationSeconds = 0.0;  // CPU answering requests and taking tiles in
  uint64_t messages = 0;             // requests and tile messages received
  LocalTiles local(job);
  bool localOpen = true;
  auto feedLocal = [&] {
    while (localOpen && local.pending() < local.wanted()) {
      std::vector<uint64_t> ids = handOut(1);
      if (ids.empty()) local.close(), localOpen = false;
      for (uint64_t id : ids) local.assign(&tiles[id]), ++perRank[0];
    }
  };
  // Sends `rank` up to `count` more tiles (none: it is done).
  auto assign = [&](int rank, uint64_t count) {
    std::vector<uint64_t> ids = handOut(count);
    if (ids.empty()) --workersOpen;
    perRank[size_t(rank)] += ids.size();
    check(MPI_Send(ids.data(), int(ids.size()), MPI_UINT64_T, rank, Assign, comm_), "send");
  };
  // Receives `rank`'s request (sleeping while it has not come) and answers it.
  auto answer = [&](int rank) {
    uint64_t count = 0;
    MPI_Request request;
    check(MPI_Irecv(&count, 1, MPI_UINT64_T, rank, Request, comm_, &request), "receive");
    waitSleeping(request);
    assign(rank, count);
  };
  // The first round in rank order, waiting for every rank's first request:
  // every rank starts with work (whoever loaded the scene first), and which
  // rank renders the first tiles does not depend on start-up timing.
  feedLocal();
  for (int rank = 1; rank < size_; ++rank) answer(rank);
  std::vector<float> buffer;
  for (;;) {
    bool busy = false;
    feedLocal();
    int flag = 0;
    MPI_Status status;
    check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &flag, &status), "probe");
    if (flag) {
      busy = true, ++messages;
      // What rank 0 does for the others, serially: the scaling model's
      // per-tile cost (docs/BENCHMARKS.md, "Strong scaling"), in this
      // thread's CPU time (its wall time would count the render threads
      // that preempt it).
      struct Timed {
        double start, &seconds;
        ~Timed() { seconds += threadCpuSeconds() - start; }
      } timed{threadCpuSeconds(), coordinationSeconds};
      if (status.MPI_TAG == Request) {
        answer(status.MPI_SOURCE);
      } else if (status.MPI_TAG == TileData) {
        int floats = 0;
        MPI_Get_count(&status, MPI_FLOAT, &floats);
        buffer.resize(size_t(floats));
        check(MPI_Recv(buffer.data(), floats, MPI_FLOAT, status.MPI_SOURCE, TileData, comm_, MPI_STATUS_IGNORE),
              "receive");
        MessageHead head;
        const char* bytes = reinterpret_cast<const char*>(buffer.data());
        const size_t size = buffer.size() * sizeof(float);
        std::memcpy(&head, bytes, sizeof(head));
        if (sizeof(head) + head.tiles * sizeof(TileHeader) > size || (!job.consumeWhereRendered && head.tiles != 1))
          throw Error(str("rank ", status.MPI_SOURCE, " sent a malformed tile message"));
        for (uint64_t k = 0; k < head.tiles; ++k) {
          TileHeader header;
          std::memcpy(&header, bytes + sizeof(head) + k * sizeof(header), sizeof(header));
          if (header.index >= next || ready[header.index])
            throw Error(str("rank ", status.MPI_SOURCE, " sent tile ", header.index, ", which it was not given"));
          RenderTile& tile = tiles[header.index];
          // Stored where rendered: only the header comes.
          if (!job.consumeWhereRendered) {
            const size_t at = (sizeof(head) + sizeof(header)) / sizeof(float);
            tile.accumulator = job.makeTile(tile.offset, tile.size);
            tile.accumulator->unpack(buffer.data() + at, buffer.size() - at);
          }
          tile.samples = header.samples, tile.invalid = header.invalid;
          ++tilesReceived;
          arrived(tile);
        }
        bytesReceived += size;
        if (head.more > 0) assign(status.MPI_SOURCE, head.more);
      } else {
        throw Error(str("rank ", status.MPI_SOURCE, " sent an unexpected message (tag ", status.MPI_TAG, ")"));
      }
    }
    for (RenderTile* tile : local.takeFinished()) arrived(*tile), busy = true;
    // Fold in tile order, as one process does: the sums are then the same
    // bits (tiles consumed where rendered are only counted here).
    while (consumed < next && ready[consumed]) {
      RenderTile& tile = tiles[consumed++];
      if (tile.accumulator) job.consume(*tile.accumulator);
      tile.accumulator.reset();
      stats.samples += tile.samples;
      stats.invalidSamples += tile.invalid;
      busy = true;
    }
    if (!localOpen && workersOpen == 0 && consumed == next && local.done()) break;
    if (!busy) local.waitForFinished(PollInterval);
  }
  if (ownProgress) ownProgress->finish();
  stats.completed = !cancelled;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  reportTileStream(stats);
  std::string counts;
  for (size_t n : perRank) counts += str(" ", n);
  logDebug("tiles rendered by ranks 0 to ", size_ - 1, ":", counts, "; received ", tilesReceived, " tiles, ",
           bytesReceived, " bytes (", tilesReceived ? bytesReceived / tilesReceived : 0, " per tile)",
           job.consumeWhereRendered ? "; each rank stored its own tiles" : "", "; rank 0 spent ",
           coordinationSeconds * 1e6 / double(std::max<uint64_t>(tilesReceived, 1)),
           " us of CPU per tile of theirs on the other ranks' requests and tiles (", messages, " messages, ",
           coordinationSeconds * 1e6 / double(std::max<uint64_t>(messages, 1)), " us each)");
  return stats;
}

void MpiTileDistribution::work(TileJob& job) {
  LocalTiles local(job);
  bool asking = false, open = true;
  std::vector<float> buffer;
  std::vector<RenderTile*> unsent;  // finished, not yet reported to rank 0
  // Tiles stored here are reported, and more asked for, in batches of half
  // the tiles kept assigned (rank 0's work is then per batch, not per tile);
  // tiles whose sums travel go one by one, at once.
  const size_t batch = job.consumeWhereRendered ? std::max<size_t>(1, local.wanted() / 2) : 1;
  while (open || !local.done() || !unsent.empty()) {
    bool busy = false;
    int flag = 0;
    MPI_Status status;
    check(MPI_Iprobe(0, Assign, comm_, &flag, &status), "probe");
    if (flag) {
      int count = 0;
      MPI_Get_count(&status, MPI_UINT64_T, &count);
      std::vector<uint64_t> ids(static_cast<size_t>(count));
      check(MPI_Recv(ids.data(), count, MPI_UINT64_T, 0, Assign, comm_, MPI_STATUS_IGNORE), "receive");
      asking = false, busy = true;
      if (ids.empty()) local.close(), open = false;
      for (uint64_t id : ids) local.assign(&job.tiles.at(id));
    }
    for (RenderTile* tile : local.takeFinished()) unsent.push_back(tile), busy = true;
    // One request in flight at a time, for what the threads here lack.
    const bool lacking = open && !asking && local.pending() + batch <= local.wanted();
    const bool report = !unsent.empty() && (unsent.size() >= batch || lacking || !open || local.pending() == 0);
    if (!report && lacking) {
      uint64_t count = local.wanted() - local.pending();
      check(MPI_Send(&count, 1, MPI_UINT64_T, 0, Request, comm_), "send");
      asking = true;
    }
    // The finished tiles, with the request riding along on the first message.
    for (size_t first = 0; report && first < unsent.size();) {
      const size_t count = job.consumeWhereRendered ? unsent.size() - first : 1;
      MessageHead head{0, count};
      if (first == 0 && lacking) head.more = local.wanted() - local.pending(), asking = true;
      std::vector<char> bytes(sizeof(head));
      std::memcpy(bytes.data(), &head, sizeof(head));
      for (size_t k = first; k < first + count; ++k) {
        const TileHeader header{unsent[k]->index, unsent[k]->samples, unsent[k]->invalid};
        const char* p = reinterpret_cast<const char*>(&header);
        bytes.insert(bytes.end(), p, p + sizeof(header));
      }
      buffer.clear();
      RenderTile& tile = *unsent[first];
      if (tile.accumulator) tile.accumulator->pack(buffer);  // else stored where rendered
      tile.accumulator.reset();
      buffer.insert(buffer.begin(), bytes.size() / sizeof(float), 0.0f);
      std::memcpy(buffer.data(), bytes.data(), bytes.size());
      MPI_Request request;
      check(MPI_Isend(buffer.data(), int(buffer.size()), MPI_FLOAT, 0, TileData, comm_, &request), "send");
      waitSleeping(request);  // until rank 0 takes it (it may be folding tiles)
      first += count;
    }
    if (report) unsent.clear();
    if (!busy) local.waitForFinished(PollInterval);
  }
}

std::vector<char> MpiTileDistribution::gatherAll(const std::vector<char>& mine) {
  uint64_t size = mine.size();
  std::vector<uint64_t> sizes(size_t(size_), 0);
  // Non-blocking and waited for sleeping, as every collective here: a rank
  // that comes first (its tiles done) must not spin a core the others render on.
  MPI_Request request;
  check(MPI_Iallgather(&size, 1, MPI_UINT64_T, sizes.data(), 1, MPI_UINT64_T, comm_, &request), "gather sizes");
  waitSleeping(request);
  std::vector<int> counts(static_cast<size_t>(size_), 0), offsets(static_cast<size_t>(size_), 0);
  uint64_t total = 0;
  for (int r = 0; r < size_; ++r) {
    if (total + sizes[size_t(r)] > uint64_t(std::numeric_limits<int>::max()))
      throw Error(str("the ranks' photons exceed 2 GiB in one pass (", total + sizes[size_t(r)],
                      " bytes): use fewer photons per pass"));
    offsets[size_t(r)] = int(total);
    counts[size_t(r)] = int(sizes[size_t(r)]);
    total += sizes[size_t(r)];
  }
  std::vector<char> all(total);
  check(MPI_Iallgatherv(mine.data(), int(size), MPI_CHAR, all.data(), counts.data(), offsets.data(), MPI_CHAR, comm_,
                       &request),
        "gather");
  waitSleeping(request);
  return all;
}

}  // namespace femto::cli
