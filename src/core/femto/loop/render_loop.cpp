#include <femto/loop/render_loop.h>

#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/core/log.h>
#include <femto/core/progress.h>
#include <femto/core/resources.h>
#include <femto/loop/pass_schedule.h>
#include <femto/loop/tile_distribution.h>
#include <femto/render/scene.h>

namespace femto {
namespace {

/// Render one tile into its own accumulator. Each pixel restarts the sampler
/// from (seed, pixel index), so the values do not depend on which thread runs it.
void renderTile(RenderTile& tile, const Sampler& prototype, int filmWidth, uint64_t seed, const TileFactory& makeTile) {
  tile.accumulator = makeTile(tile.offset, tile.size);
  std::unique_ptr<Sampler> sampler = prototype.clone();
  const uint32_t spp = prototype.sampleCount();
  for (int y = tile.offset.y; y < tile.offset.y + tile.size.y; ++y)
    for (int x = tile.offset.x; x < tile.offset.x + tile.size.x; ++x) {
      sampler->startPixel(seed, uint64_t(y) * uint64_t(filmWidth) + uint64_t(x));
      for (uint32_t s = 0; s < spp; ++s) {
        Point2f jitter = sampler->next2D();
        Point2f pos(float(x) + jitter.x, float(y) + jitter.y);
        if (!tile.accumulator->addSample(Point2i(x, y), pos, *sampler)) ++tile.invalid;
        ++tile.samples;
        sampler->advance();
      }
    }
}

/// Computes one sample at a film position and splats it into a block;
/// returns false when the block refused the value as invalid.
using SplatFunction = std::function<bool(const Point2f& filmPos, Sampler& sampler, ImageBlock& block)>;

/// The image accumulator: one ImageBlock (tile plus filter border).
class ImageBlockTile final : public TileAccumulator {
 public:
  ImageBlockTile(const Point2i& offset, const Point2i& size, const ReconstructionFilter* filter, int channels,
                 const SplatFunction& splatFn)
      : block(offset, size, filter, channels), splatFn_(splatFn) {}
  bool addSample(const Point2i&, const Point2f& pos, Sampler& sampler) override {
    return splatFn_(pos, sampler, block);
  }
  void pack(std::vector<float>& out) const override { block.pack(out); }
  void unpack(const float* data, size_t count) override { block.unpack(data, count); }
  ImageBlock block;

 private:
  const SplatFunction& splatFn_;
};

/// Tiles rendering or waiting for an earlier one to be consumed: the
/// pipeline's token limit, in the task arena the render runs in.
size_t tilesInFlight() { return size_t(2 * tbb::this_task_arena::max_concurrency()); }

}  // namespace

int tileSideWithin(double bytesPerPixel, size_t tilesInFlight) {
  if (bytesPerPixel <= 0.0) return RenderTileSize;
  const double pixelsPerTile = TileMemoryBound / (double(tilesInFlight) * bytesPerPixel);
  if (pixelsPerTile < 1.0)
    throw Error(str("one pixel of a tile holds ", formatBytes(bytesPerPixel), " and ", tilesInFlight,
                    " tiles are in flight (two per thread): ", formatBytes(bytesPerPixel * double(tilesInFlight)),
                    ", above the ", formatBytes(TileMemoryBound),
                    " the render loop allows; use fewer time bins (or fewer threads, -t)"));
  return std::clamp(int(std::sqrt(pixelsPerTile)), 1, RenderTileSize);
}

void TileAccumulator::pack(std::vector<float>&) const {
  throw Error("this integrator's tiles cannot be sent to another process (a distributed render needs tiles that pack)");
}

void TileAccumulator::unpack(const float*, size_t) {
  throw Error("this integrator's tiles cannot be received from another process");
}

namespace {

TileDistribution* gDistribution = nullptr;

}  // namespace

void setTileDistribution(TileDistribution* distribution) { gDistribution = distribution; }
TileDistribution* tileDistribution() { return gDistribution; }

std::vector<RenderTile> cropWindowTiles(const Scene& scene, int side) {
  const Film& film = scene.sensor().film();
  const Point2i offset = film.cropOffset(), size = film.cropSize();
  std::vector<RenderTile> tiles;
  for (int y = 0; y < size.y; y += side)
    for (int x = 0; x < size.x; x += side) {
      RenderTile t;
      t.index = tiles.size();
      t.offset = Point2i(offset.x + x, offset.y + y);
      t.size = Point2i(std::min(side, size.x - x), std::min(side, size.y - y));
      tiles.push_back(std::move(t));
    }
  return tiles;
}

void renderClaimedTiles(const TileJob& job, const std::function<RenderTile*()>& claim,
                        const std::function<void(RenderTile&)>& deliver) {
  const Film& film = job.scene.sensor().film();
  const Sampler& prototype = job.scene.sensor().sampler();
  const uint64_t seed = prototype.cameraSeed(job.options.seed);
  std::optional<tbb::task_arena> arena;
  if (job.options.threads > 0) arena.emplace(job.options.threads);
  // The pipeline's hand-offs stated for ThreadSanitizer (base/thread_edges.h):
  // each serial stage runs its items in order, and a tile passes from the
  // stage that made it to the next one.
  char claimOrder = 0, deliverOrder = 0;
  auto claimStage = [&](tbb::flow_control& fc) -> RenderTile* {
    acquireFrom(&claimOrder);
    RenderTile* tile = claim();
    releaseTo(&claimOrder);
    if (!tile)
      fc.stop();
    else
      releaseTo(tile);
    return tile;
  };
  auto renderStage = [&](RenderTile* tile) {
    acquireFrom(tile);
    renderTile(*tile, prototype, film.size().x, seed, job.makeTile);
    // A tile whose pixels are stored alone is stored by the thread that
    // rendered it, in parallel with the others (the fold of a many-bin
    // volume would otherwise be one thread's work).
    if (job.consumeWhereRendered) {
      job.consume(*tile->accumulator);
      tile->accumulator.reset();
    }
    releaseTo(tile);
    return tile;
  };
  auto deliverStage = [&](RenderTile* tile) {
    acquireFrom(&deliverOrder);
    acquireFrom(tile);
    deliver(*tile);
    releaseTo(&deliverOrder);
  };
  auto work = [&] {
    // A pipeline: tiles enter in order, render in parallel, and leave in
    // order. The token limit bounds how many tiles exist at once (rendering
    // or waiting for an earlier tile), which bounds memory for large tiles
    // (transient films) and keeps the consumer's sums in a fixed order.
    ForkJoinEdges edges;
    tbb::parallel_pipeline(
        tilesInFlight(),
        tbb::make_filter<void, RenderTile*>(tbb::filter_mode::serial_in_order, edges.task(claimStage)) &
            tbb::make_filter<RenderTile*, RenderTile*>(tbb::filter_mode::parallel, edges.task(renderStage)) &
            tbb::make_filter<RenderTile*, void>(tbb::filter_mode::serial_in_order, edges.task(deliverStage)));
    edges.join();
  };
  if (arena)
    executeInArena(*arena, work);
  else
    work();
}

RenderStats renderTileStream(const Scene& scene, const RenderOptions& options, const TileFactory& makeTile,
                             const TileConsumer& consume, double tileBytesPerPixel, ProgressReporter* jobProgress,
                             bool consumeWhereRendered) {
  std::optional<tbb::task_arena> arena;
  if (options.threads > 0) arena.emplace(options.threads);
  const size_t tokens = arena ? arena->execute(tilesInFlight) : tilesInFlight();
  const int side = tileSideWithin(tileBytesPerPixel, tokens);
  TileJob job{scene, options, makeTile, consume, jobProgress, side, cropWindowTiles(scene, side), consumeWhereRendered};
  if (TileDistribution* distribution = tileDistribution()) return distribution->run(job);
  const Point2i crop = scene.sensor().film().cropSize();
  std::optional<ProgressReporter> ownProgress;
  ProgressReporter& progress = jobProgress ? *jobProgress
                                           : ownProgress.emplace("Rendering", uint64_t(crop.x) * uint64_t(crop.y),
                                                                 options.progress, options.onProgress);
  const auto start = std::chrono::steady_clock::now();
  bool cancelled = false;
  size_t next = 0;
  RenderStats stats;
  auto claim = [&]() -> RenderTile* {
    if (next == job.tiles.size()) return nullptr;
    if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
      cancelled = true;
      return nullptr;
    }
    return &job.tiles[next++];
  };
  auto deliver = [&](RenderTile& tile) {
    progress.update(uint64_t(tile.size.x) * uint64_t(tile.size.y));
    if (tile.accumulator) consume(*tile.accumulator);  // else stored where rendered
    tile.accumulator.reset();
    stats.samples += tile.samples;
    stats.invalidSamples += tile.invalid;
  };
  renderClaimedTiles(job, claim, deliver);
  if (ownProgress) ownProgress->finish();
  stats.completed = !cancelled;
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  reportTileStream(stats);
  return stats;
}

void reportTileStream(const RenderStats& stats) {
  if (stats.invalidSamples > 0) logWarn(stats.invalidSamples, " samples were NaN/Inf/negative and were dropped");
  if (!stats.completed) logWarn("rendering was cancelled; the image contains only the tiles finished so far");
}

namespace {

/// Splat `splatFn` through the film's reconstruction filter into `result`
/// (crop-window sized block), tiles merged in tile order.
RenderStats renderSplatTiles(const Scene& scene, const RenderOptions& options, const SplatFunction& splatFn,
                             ImageBlock& result, ProgressReporter* progress = nullptr) {
  const ReconstructionFilter* filter = scene.sensor().film().filter();
  const int channels = result.channelCount();
  auto makeTile = [&](const Point2i& offset, const Point2i& size) -> std::unique_ptr<TileAccumulator> {
    return std::make_unique<ImageBlockTile>(offset, size, filter, channels, splatFn);
  };
  // Merged in tile order: the floating-point sums are then the same whatever
  // the number of threads or the schedule.
  auto consume = [&](TileAccumulator& tile) { result.merge(static_cast<ImageBlockTile&>(tile).block); };
  return renderTileStream(scene, options, makeTile, consume, 0.0, progress);
}

}  // namespace

RenderStats renderTiles(const Scene& scene, const RenderOptions& options, const SampleFunction& sampleFn,
                        ImageBlock& result) {
  return renderSplatTiles(
      scene, options,
      [&](const Point2f& pos, Sampler& sampler, ImageBlock& block) { return block.put(pos, sampleFn(pos, sampler)); },
      result);
}

RenderStats renderChannelTiles(const Scene& scene, const RenderOptions& options, const ChannelSampleFunction& sampleFn,
                               ImageBlock& result) {
  refuseTimeLimit(options, "this integrator (arbitrary output channels)");
  return renderSplatTiles(
      scene, options,
      [&](const Point2f& pos, Sampler& sampler, ImageBlock& block) {
        std::vector<float> values(size_t(block.channelCount()), 0.0f);
        sampleFn(pos, sampler, values.data());
        return block.put(pos, values.data());
      },
      result);
}

RenderStats renderSteadyImage(const Scene& scene, const RenderOptions& options,
                              const CameraRadianceFunction& radiance) {
  return renderSteadyPasses(scene, options, 1, [&](int) { return radiance; });
}

uint64_t passSeed(uint64_t seed, int pass) { return pass == 0 ? seed : mixSeed(seed, uint64_t(pass)); }

void accumulatePassStats(RenderStats& total, const RenderStats& pass) {
  total.samples += pass.samples;
  total.invalidSamples += pass.invalidSamples;
  total.seconds += pass.seconds;
  total.completed = pass.completed;
}

RenderStats renderSteadyPasses(const Scene& scene, const RenderOptions& options, int passes,
                               const PassRadianceFunction& radianceOf) {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  // Every pass splats the same number of samples per pixel into one block:
  // its developed value (weighted sum / weight sum) is the mean of the passes.
  ImageBlock result(film.cropOffset(), film.cropSize(), film.filter());
  PassSchedule schedule(options, passes);
  const double cpuStart = clockSeconds(RenderClock::Cpu);
  // One bar for all passes: its ETA is that of the whole render.
  const uint64_t pixels = uint64_t(film.cropSize().x) * uint64_t(film.cropSize().y);
  ProgressReporter progress("Rendering", pixels * uint64_t(schedule.expectedPasses()), options.progress,
                            options.onProgress);
  RenderStats stats;
  for (int pass = 0; schedule.startPass(pass); ++pass) {
    progress.setTotal(pixels * uint64_t(schedule.expectedPasses()));
    CameraRadianceFunction radiance = radianceOf(pass);
    auto sampleFn = [&](const Point2f& filmPos, Sampler& sampler) -> Color3f {
      Ray ray;
      Color3f weight = sensor.sampleRay(filmPos, sampler.next2D(), ray);
      if (weight.isBlack()) return Color3f(0.0f);
      return weight * radiance(ray, sampler);
    };
    RenderOptions passOptions = options;
    passOptions.seed = passSeed(options.seed, pass);
    accumulatePassStats(stats, renderSplatTiles(
                                   scene, passOptions,
                                   [&](const Point2f& pos, Sampler& sampler, ImageBlock& block) {
                                     return block.put(pos, sampleFn(pos, sampler));
                                   },
                                   result, &progress));
    if (!stats.completed) break;  // a cancelled pass is partial: not counted
    ++stats.passes;
  }
  stats.timeLimitReached = schedule.limitReached();
  stats.cpuSeconds = clockSeconds(RenderClock::Cpu) - cpuStart;
  progress.setTotal(pixels * uint64_t(std::max(stats.passes, 1)));
  progress.finish();
  if (!options.output.empty()) film.develop(result, options.output);
  return stats;
}

void refuseTimeLimit(const RenderOptions& options, const std::string& integrator) {
  if (options.timeLimit > 0.0 || options.passes > 0)
    throw Error(str(integrator, " renders in one pass and cannot render ", options.timeLimit > 0.0 ? "to a time limit" : "a given number of passes",
                    " (--time-limit, --passes): render it with a sample count (--spp) instead"));
}

}  // namespace femto
