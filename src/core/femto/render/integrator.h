#pragma once
// Integrators render a scene. SamplingIntegrator covers the common case of
// an estimator of radiance along a camera ray: the core's render loop drives
// it over tiles in parallel.
#include <atomic>
#include <cstdint>
#include <filesystem>

#include <femto/core/object.h>
#include <femto/core/progress.h>
#include <femto/core/properties.h>
#include <femto/math/ray.h>
#include <femto/math/spectrum.h>

namespace femto {

class Scene;
class Sampler;

/// The clock a render's time limit is measured on: wall time, or the
/// process's CPU time (user + system over all threads).
enum class RenderClock { Wall, Cpu };

struct RenderOptions {
  int threads = 0;                         // 0 = all cores
  uint64_t seed = 0;                       // base seed; the image is a function of (scene, seed, passes)
  /// Passes: independent renders of the whole film (the sampler's samples per
  /// pixel each, pass seeds passSeed in render_loop.h) averaged with equal
  /// weights. 0: the integrator's own count (transient_beams' `passes`, else 1).
  int passes = 0;
  /// Seconds (> 0): passes repeat until `timeClock` says the budget would be
  /// exceeded by one more (pass_schedule.h); `passes`, if set, caps them. The
  /// result is bitwise the render of the passes reached (RenderStats::passes).
  double timeLimit = 0.0;
  RenderClock timeClock = RenderClock::Wall;
  std::filesystem::path output;            // output file (the film may write previews beside it); empty: nothing written
  bool progress = true;                    // progress bar (only drawn on a TTY)
  const std::atomic<bool>* cancel = nullptr;  // set to stop early (Ctrl-C); a valid partial image is written
  ProgressCallback onProgress;             // also given what the bar shows (empty: nothing); for embedding (Python)
};

/// What a render did, for the CLI and tests.
struct RenderStats {
  bool completed = false;
  uint64_t samples = 0;
  uint64_t invalidSamples = 0;  // NaN/Inf/negative values refused by the film (reported, never added)
  double seconds = 0.0;
  double cpuSeconds = 0.0;  // process CPU time (all threads) while the passes rendered; 0 where not measured
  int passes = 0;           // whole passes rendered (RenderOptions::passes; a cancelled one is not counted)
  bool timeLimitReached = false;  // a time limit, not the pass count, ended the render
};

class Integrator : public Object {
 public:
  ObjectKind kind() const override { return ObjectKind::Integrator; }
  virtual RenderStats render(const Scene& scene, const RenderOptions& options) const = 0;
  /// Does render() trace the laser an NLOS capture meter holds
  /// (NlosSensor::nestedLaser)? One that does not would render such a scene
  /// black: the scene refuses the pair (scene.cpp).
  virtual bool tracesNestedLaser() const { return false; }
};

class SamplingIntegrator : public Integrator {
 public:
  /// Radiance arriving at the ray origin from direction -ray.d.
  virtual Color3f Li(const Ray& ray, const Scene& scene, Sampler& sampler) const = 0;
  /// Tiles in parallel over the sensor's film (see render_loop.h).
  RenderStats render(const Scene& scene, const RenderOptions& options) const override;
};

}  // namespace femto
