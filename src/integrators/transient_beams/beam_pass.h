#pragma once
// One pass of progressive transient photon beams: the photons traced for the
// pass, their beam map and surface photon map, and the pass's kernel radii.
// It renders camera samples like any transient integrator (the orchestrator,
// transient_beams.cpp, hands one per pass to renderTransientPasses and frees
// it when the pass ends). Immutable once built; sample() is thread-safe
// (each thread gets its own CameraTracer scratch space).
#include <chrono>
#include <cstdint>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

#include <femto/render/transient_integrator.h>
#include <transient_beams/beam_map.h>
#include <transient_beams/beam_settings.h>
#include <transient_beams/camera_tracer.h>
#include <transient_beams/photon_tracer.h>
#include <transient_beams/surface_photon_map.h>

namespace femto::beams {

class BeamPass final : public TransientIntegrator {
 public:
  /// Trace pass `pass`'s photons (seeded by `seed`; OPLs past `horizon` are
  /// not stored) and build its maps with the pass's radii. `settings` must be
  /// resolved (radii known).
  BeamPass(const Scene& scene, const BeamSettings& settings, int pass, uint64_t seed, double horizon);
  /// Maps over photons traced elsewhere (tests build passes by hand). With a
  /// scene, the beam map's pieces follow its cost rule (beam_map.h,
  /// BeamMapOptions::crossingDensity) for the scene's camera samples per pass;
  /// without, fixed pieces of a few radii.
  BeamPass(const BeamSettings& settings, int pass, PhotonPass traced, const Scene* scene = nullptr,
           double horizon = Infinity);

  void sample(const Scene& scene, const Ray& ray, Sampler& sampler, RadianceRecorder& recorder) const override;
  bool countsCameraSegment() const override { return settings_.observerTime; }

  const BeamMap& beamMap() const { return beams_; }
  const SurfacePhotonMap& photonMap() const { return photons_; }
  const PassMaps& maps() const { return maps_; }
  std::string toString() const override;

  /// The camera side's work so far, summed over threads (call between renders).
  CameraStatistics cameraStatistics() const;
  /// Wall seconds spent tracing the photons and building the two maps.
  double traceSeconds() const { return traceSeconds_; }
  double buildSeconds() const { return buildSeconds_; }
  /// Photons traced: fewer than the maps' photonCount when no surface stores photons.
  uint64_t tracedPhotons() const { return tracedPhotons_; }

 private:
  std::chrono::steady_clock::time_point buildStart_;  // first member: initialised before the maps are built
  BeamSettings settings_;
  BeamMap beams_;
  SurfacePhotonMap photons_;
  PassMaps maps_;
  double traceSeconds_ = 0.0, buildSeconds_ = 0.0;
  uint64_t tracedPhotons_ = 0;
  mutable tbb::enumerable_thread_specific<CameraScratch> threads_;
};

}  // namespace femto::beams
