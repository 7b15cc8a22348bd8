#pragma once
// The parallel render loop: square tiles over TBB, one sampler clone and one
// ImageBlock per tile, per-pixel seeding (mixSeed(seed, pixel index)) so the
// result does not depend on thread count; finished tiles are merged in tile
// order. A progress bar with ETA is drawn on a TTY. On cancellation the tiles
// done so far are developed into a valid partial image.
#include <functional>

#include <femto/render/image_block.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>

namespace femto {

class Scene;

/// Called per sample: returns the value to splat at `filmPos` (full-film pixels).
using SampleFunction = std::function<Color3f(const Point2f& filmPos, Sampler& sampler)>;

/// Render every pixel of the scene sensor's crop window with `sampleFn`,
/// sampleCount() samples per pixel, into `result` (crop-window sized block).
RenderStats renderTiles(const Scene& scene, const RenderOptions& options, const SampleFunction& sampleFn,
                        ImageBlock& result);

/// Called per sample: writes result.channelCount() values for `filmPos`
/// (arbitrary output variables: any sign; NaN/Inf are refused and counted).
using ChannelSampleFunction = std::function<void(const Point2f& filmPos, Sampler& sampler, float* values)>;

/// renderTiles for blocks of any number of channels.
RenderStats renderChannelTiles(const Scene& scene, const RenderOptions& options, const ChannelSampleFunction& sampleFn,
                               ImageBlock& result);

}  // namespace femto
