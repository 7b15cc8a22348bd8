#include <femto/render/render_loop.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <vector>

#include <femto/core/log.h>
#include <femto/core/progress.h>
#include <femto/render/scene.h>

namespace femto {
namespace {

constexpr int TileSize = 32;

/// Computes one sample at a film position and splats it into a block;
/// returns false when the block refused the value as invalid.
using SplatFunction = std::function<bool(const Point2f& filmPos, Sampler& sampler, ImageBlock& block)>;

struct Tile {
  Point2i offset, size;
  std::unique_ptr<ImageBlock> block;  // null until rendered (or when cancelled before)
  uint64_t samples = 0, invalid = 0;
};

std::vector<Tile> makeTiles(const Point2i& offset, const Point2i& size) {
  std::vector<Tile> tiles;
  for (int y = 0; y < size.y; y += TileSize)
    for (int x = 0; x < size.x; x += TileSize) {
      Tile t;
      t.offset = Point2i(offset.x + x, offset.y + y);
      t.size = Point2i(std::min(TileSize, size.x - x), std::min(TileSize, size.y - y));
      tiles.push_back(std::move(t));
    }
  return tiles;
}

/// Render one tile into its own block. Each pixel restarts the sampler from
/// (seed, pixel index), so the values do not depend on which thread runs it.
void renderTile(Tile& tile, const Sampler& prototype, int filmWidth, uint64_t seed, const SplatFunction& splatFn,
                const ReconstructionFilter* filter, int channels) {
  tile.block = std::make_unique<ImageBlock>(tile.offset, tile.size, filter, channels);
  std::unique_ptr<Sampler> sampler = prototype.clone();
  const uint32_t spp = prototype.sampleCount();
  for (int y = tile.offset.y; y < tile.offset.y + tile.size.y; ++y)
    for (int x = tile.offset.x; x < tile.offset.x + tile.size.x; ++x) {
      sampler->startPixel(seed, uint64_t(y) * uint64_t(filmWidth) + uint64_t(x));
      for (uint32_t s = 0; s < spp; ++s) {
        Point2f jitter = sampler->next2D();
        Point2f pos(float(x) + jitter.x, float(y) + jitter.y);
        if (!splatFn(pos, *sampler, *tile.block)) ++tile.invalid;
        ++tile.samples;
        sampler->advance();
      }
    }
}

RenderStats renderSplatTiles(const Scene& scene, const RenderOptions& options, const SplatFunction& splatFn,
                             ImageBlock& result) {
  const Film& film = scene.sensor().film();
  const Sampler& prototype = scene.sensor().sampler();
  std::vector<Tile> tiles = makeTiles(film.cropOffset(), film.cropSize());
  const uint64_t pixelsTotal = uint64_t(film.cropSize().x) * uint64_t(film.cropSize().y);
  ProgressReporter progress("Rendering", pixelsTotal, options.progress);
  std::atomic<bool> cancelled{false};

  auto work = [&] {
    // grainsize 1: tiles are coarse enough, and small grains balance uneven scenes.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, tiles.size(), 1), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
          cancelled = true;
          return;
        }
        renderTile(tiles[i], prototype, film.size().x, options.seed, splatFn, film.filter(), result.channelCount());
        progress.update(uint64_t(tiles[i].size.x) * uint64_t(tiles[i].size.y));
      }
    });
  };
  if (options.threads > 0) {
    tbb::task_arena arena(options.threads);
    arena.execute(work);
  } else {
    work();
  }
  progress.finish();

  // Merge in tile order, after all tiles are done: the floating-point sums
  // are then the same whatever the number of threads or the schedule.
  RenderStats stats;
  for (const Tile& tile : tiles) {
    if (!tile.block) continue;
    result.merge(*tile.block);
    stats.samples += tile.samples;
    stats.invalidSamples += tile.invalid;
  }
  stats.completed = !cancelled;
  stats.seconds = progress.elapsedSeconds();
  if (stats.invalidSamples > 0)
    logWarn(stats.invalidSamples, " samples were NaN/Inf/negative and were dropped");
  if (cancelled) logWarn("rendering was cancelled; the image contains only the tiles finished so far");
  return stats;
}

}  // namespace

RenderStats renderTiles(const Scene& scene, const RenderOptions& options, const SampleFunction& sampleFn,
                        ImageBlock& result) {
  return renderSplatTiles(scene, options, [&](const Point2f& pos, Sampler& sampler, ImageBlock& block) {
    return block.put(pos, sampleFn(pos, sampler));
  }, result);
}

RenderStats renderChannelTiles(const Scene& scene, const RenderOptions& options, const ChannelSampleFunction& sampleFn,
                               ImageBlock& result) {
  return renderSplatTiles(scene, options, [&](const Point2f& pos, Sampler& sampler, ImageBlock& block) {
    std::vector<float> values(size_t(block.channelCount()), 0.0f);
    sampleFn(pos, sampler, values.data());
    return block.put(pos, values.data());
  }, result);
}

}  // namespace femto
