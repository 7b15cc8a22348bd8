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

struct RenderOptions {
  int threads = 0;                         // 0 = all cores
  uint64_t seed = 0;                       // base seed; the image is a function of (scene, seed)
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
