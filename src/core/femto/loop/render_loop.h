#pragma once
// The parallel render loop: square tiles rendered in parallel (TBB), one
// sampler clone per tile, per-pixel seeding (mixSeed(seed, pixel index)) so the
// result does not depend on thread count. Each finished tile is handed to a
// consumer serially and in tile order (out-of-order tiles wait, at most a few
// per thread), then freed: memory grows with the tiles in flight, not with the
// image. A progress bar with ETA is drawn on a TTY. On cancellation the tiles
// already started are finished and consumed; the rest are skipped.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <femto/math/ray.h>
#include <femto/render/image_block.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>

namespace femto {

class ProgressReporter;
class Scene;

/// What one tile accumulates into; the loop feeds it every camera sample of the tile.
class TileAccumulator {
 public:
  virtual ~TileAccumulator() = default;
  /// One camera sample at continuous film position `pos` (full-film pixels),
  /// drawn inside `pixel`. Returns false when the sample was invalid (NaN,
  /// infinite, negative) and was dropped.
  virtual bool addSample(const Point2i& pixel, const Point2f& pos, Sampler& sampler) = 0;
  /// The sums accumulated so far as floats, to send the tile to another
  /// process (tile_distribution.h); unpack restores them, exactly, into an
  /// accumulator the same factory made for the same tile. By default a tile
  /// cannot travel (Error).
  virtual void pack(std::vector<float>& out) const;
  virtual void unpack(const float* data, size_t count);
};

/// Creates the accumulator of the tile at `offset` (film pixels) of `size`.
using TileFactory = std::function<std::unique_ptr<TileAccumulator>(const Point2i& offset, const Point2i& size)>;
/// Receives each finished tile, one at a time, in tile order (row-major over
/// the crop window), or, for renderTileStream's consumeWhereRendered, on the
/// thread that rendered it; the accumulator is destroyed right after.
using TileConsumer = std::function<void(TileAccumulator& tile)>;

/// Side length of the square tiles (pixels), unless their memory needs less.
inline constexpr int RenderTileSize = 32;

/// The most memory the tiles in flight may hold together (transient tiles
/// hold bins x 3 floats per pixel: at 2^20 bins a 32x32 tile alone is 12 GiB).
inline constexpr double TileMemoryBound = double(1ull << 30);

/// The side of square tiles such that `tilesInFlight` tiles of
/// `bytesPerPixel` stay within TileMemoryBound: RenderTileSize, or less.
/// Throws an Error naming the sizes when even one-pixel tiles do not fit.
int tileSideWithin(double bytesPerPixel, size_t tilesInFlight);

/// Render every pixel of the scene sensor's crop window, sampleCount() samples
/// per pixel, into per-tile accumulators, streaming them to `consume`.
/// `tileBytesPerPixel`: what an accumulator holds per pixel, which shrinks
/// the tiles when needed (tileSideWithin). Each pixel's samples depend only
/// on the seed and the pixel, so the tile side changes no value.
/// `progress`: the bar of a longer job this stream is part of (several
/// passes, frames written after), advanced by one per pixel; null: a bar of
/// its own, when options.progress.
/// `consumeWhereRendered`: each tile is consumed by the thread that rendered
/// it, in parallel and in no fixed order (when several processes share the
/// tiles, tile_distribution.h, by the process that rendered it). Only for a
/// thread-safe consumer whose result for a pixel depends on its tile alone.
RenderStats renderTileStream(const Scene& scene, const RenderOptions& options, const TileFactory& makeTile,
                             const TileConsumer& consume, double tileBytesPerPixel = 0.0,
                             ProgressReporter* progress = nullptr, bool consumeWhereRendered = false);

/// Called per sample: returns the value to splat at `filmPos` (full-film pixels).
using SampleFunction = std::function<Color3f(const Point2f& filmPos, Sampler& sampler)>;

/// The steady case: splat `sampleFn` through the film's reconstruction filter
/// into `result` (crop-window sized block), tiles merged in tile order.
RenderStats renderTiles(const Scene& scene, const RenderOptions& options, const SampleFunction& sampleFn,
                        ImageBlock& result);

/// Called per sample: writes result.channelCount() values for `filmPos`
/// (arbitrary output variables: any sign; NaN/Inf are refused and counted).
using ChannelSampleFunction = std::function<void(const Point2f& filmPos, Sampler& sampler, float* values)>;

/// renderTiles for blocks of any number of channels: one pass, so a render
/// asked for a time limit or a pass count (RenderOptions) is refused
/// (refuseTimeLimit) before any work.
RenderStats renderChannelTiles(const Scene& scene, const RenderOptions& options, const ChannelSampleFunction& sampleFn,
                               ImageBlock& result);

/// Radiance arriving along a camera ray (before the sensor's importance weight).
using CameraRadianceFunction = std::function<Color3f(const Ray& ray, Sampler& sampler)>;

/// The steady image of `radiance` through the scene's sensor: per sample a
/// sensor ray (aperture sample first, then `radiance`'s), weighted by the
/// sensor's importance, splatted with renderTiles and developed by the film
/// into options.output (when not empty).
RenderStats renderSteadyImage(const Scene& scene, const RenderOptions& options,
                              const CameraRadianceFunction& radiance);

/// The seed of pass `pass` of a progressive render: pass 0 keeps `seed` (a
/// one-pass render is the ordinary one), later passes mix in their index.
uint64_t passSeed(uint64_t seed, int pass);

/// Progressive rendering (photon beams, Jarosz et al. 2011 "Progressive
/// Photon Beams"): `passes` independent estimates of the whole image, each
/// seeded with passSeed, averaged with equal weights (RenderOptions::passes
/// and timeLimit override the count: pass_schedule.h). `radianceOf(pass)` is
/// called serially before each pass; what it captures (that pass's photon
/// maps) is released when the pass ends, so memory is that of one pass.
/// renderSteadyImage is the one-pass case. A cancel stops after the pass in flight.
using PassRadianceFunction = std::function<CameraRadianceFunction(int pass)>;
RenderStats renderSteadyPasses(const Scene& scene, const RenderOptions& options, int passes,
                               const PassRadianceFunction& radianceOf);

/// Throws an Error naming `integrator` when `options` ask for a time limit or
/// a pass count, which an integrator that renders in one pass cannot honour.
void refuseTimeLimit(const RenderOptions& options, const std::string& integrator);

/// Adds a pass's statistics to a running total (samples and invalid samples
/// summed, seconds summed, completed only while every pass completed).
void accumulatePassStats(RenderStats& total, const RenderStats& pass);

}  // namespace femto
