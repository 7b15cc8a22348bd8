#pragma once
// The camera side of transient photon beams (Marco et al. 2017, sec. 4), per
// thread: one camera sample against one pass's photon maps.
//
// A camera path follows index-matched boundaries and specular chains (mirrors,
// glass) and ends at the first surface with a non-specular BSDF. Along the
// way every piece inside a medium gathers the beams passing within the
// kernel radius (rayBeamIntersect): each pair adds
//
//   throughput sigma_s(x) f_p(-ray.d, -beam.d) T_cam(tRay) / S(tRay) T_beam(tBeam) / S(tBeam) Phi kernel / N
//
// (S: the probability that the Russian roulette of the beam, or of the
// segment's gather, let it reach tBeam or tRay, beam_roulette.h)
// spread over the pair's OPL interval (camera OPL + beam OPL + overlap), N the
// photons traced in the pass. With volume_estimator = "points" the map holds
// photon points (zero-length beams) and each point within the radius of the
// segment adds the same with the 2D kernel 1/(pi r^2) and T_beam = 1, at one
// OPL (rayPointIntersect, ray_point.h). The camera ray itself is only attenuated in
// media (T_cam to the surface), never scattered: medium radiance comes from
// the beams alone. At the final surface, direct light comes from next-event
// estimation (through media, with its OPL) and indirect light and caustics
// from the surface photons within the surface radius (uniform disc kernel,
// Jensen 2001 eq. 7.6, over the disc's area on the surface,
// surface_coverage.h), each from the camera OPL + the photon's OPL timed
// along its last leg to the gather point (surface_photon_map.h), spread over
// a causal time kernel of width w after it (beam_settings.h). Emitters seen
// directly or through specular chains are recorded as found.
//
// Time of emission: every contribution is computed for a Dirac emission at
// OPL 0 and reported with the pulse of the emitter its light came from (the
// one a beam or surface photon names, the one NEE sampled, the one seen),
// so the film convolves it with the pulse exactly (RadianceRecorder::addPulsed):
// no emission times are sampled, and continuous emission works too.
//
// Transport split (no light counted twice): beams carry everything arriving
// at a medium point (store = all) or only unscattered light (store = single:
// single scattering, multiple scattering in media is then absent); NEE carries
// light straight from emitters to the surface; surface photons carry what
// scattered or bounced specularly at least once. Depth (camera + photon
// segments) is checked per contribution against max_depth.
#include <cstdint>
#include <limits>
#include <vector>

#include <femto/math/ray.h>
#include <transient_beams/beam_map.h>
#include <transient_beams/beam_settings.h>
#include <transient_beams/surface_photon_map.h>

namespace femto {
class Scene;
class Sampler;
class RadianceRecorder;
struct SurfaceInteraction;
}  // namespace femto

namespace femto::beams {

/// Work counters of the camera side (per thread, summed per pass): what the
/// estimates cost, for the statistics the integrator logs and the benchmarks
/// read (docs/design/photon-beams.md, "Cost").
struct CameraStatistics {
  uint64_t cameraRays = 0;      // camera samples traced
  uint64_t segments = 0;        // camera segments in media: beam map queries
  uint64_t piecesCrossed = 0;   // beam map piece boxes the queries' segments crossed (BeamMap::queryUnsorted)
  uint64_t candidates = 0;      // beams the queries returned: rayBeamIntersect calls (ray x beam queries)
  uint64_t pairHits = 0;        // pairs within the kernel radius that deposited an estimate
  uint64_t surfaceQueries = 0;  // surface photon map queries
  uint64_t surfacePhotons = 0;  // photons those found within the surface radius

  CameraStatistics& operator+=(const CameraStatistics& o) {
    cameraRays += o.cameraRays, segments += o.segments, candidates += o.candidates, pairHits += o.pairHits;
    piecesCrossed += o.piecesCrossed;
    surfaceQueries += o.surfaceQueries, surfacePhotons += o.surfacePhotons;
    return *this;
  }
};

/// A thread's reusable state: query results, the beam map's visit marks and
/// the work counters.
struct CameraScratch {
  std::vector<uint32_t> found;
  BeamMap::VisitMarks marks;
  CameraStatistics stats;
};

/// What one pass gives the camera side (all immutable, shared by threads).
struct PassMaps {
  const BeamMap& beams;
  const SurfacePhotonMap& photons;
  float beamRadius = 0.0f;
  float surfaceRadius = 0.0f;
  float surfaceTimeWidth = 0.0f;  // the surface photons' causal time kernel (OPL; 0: instants)
  uint64_t photonCount = 1;      // photons traced in the pass (the surface estimate's N)
  uint64_t beamPhotonCount = 1;  // those that left beams (the beam estimate's N)
};

class CameraTracer {
 public:
  /// `scratch`: one per thread, kept between calls.
  CameraTracer(const BeamSettings& settings, const PassMaps& maps, CameraScratch& scratch)
      : settings_(settings), maps_(maps), scratch_(scratch.found), marks_(scratch.marks), stats_(scratch.stats) {}

  /// Trace one camera sample along `ray` (OPL 0 at the sensor).
  void sample(const Scene& scene, const Ray& ray, Sampler& sampler, RadianceRecorder& recorder);

 private:
  struct Path;
  // The steps of sample(), in path order.
  /// The current segment inside a medium, up to `si` when `hit`: gathers the
  /// beams along it and attenuates the throughput; false when the path ends.
  bool crossMedium(const Scene& scene, Path& path, bool hit, const SurfaceInteraction& si, Sampler& sampler,
                   RadianceRecorder& recorder);
  /// Whether emission the current segment finds counts (hide_emitters, max_depth).
  bool emissionCounts(const Path& path) const;
  /// The path left the scene: environment emission.
  void recordEnvironment(const Scene& scene, const Path& path, RadianceRecorder& recorder) const;
  /// The path reached `si`: its emission, if it is an emitter.
  void recordEmission(const Scene& scene, const Path& path, const SurfaceInteraction& si,
                      RadianceRecorder& recorder) const;
  /// A scattering surface: its delay, then NEE and surface photons at a
  /// smooth BSDF; true when the path continues along a specular component.
  bool scatterOnSurface(const Scene& scene, Path& path, const SurfaceInteraction& si, Sampler& sampler,
                        RadianceRecorder& recorder);
  /// Sample the BSDF at `si`; true (and the path turned) for a specular
  /// component within max_depth.
  bool followSpecular(Path& path, const SurfaceInteraction& si, Sampler& sampler) const;
  /// Time gating (time_gating; docs/design/photon-beams.md, "Time gating"):
  /// one draw per gather decides whether the deposits that land wholly
  /// before the film's window are made this time (weighted by 1 /
  /// before_window_rate) or skipped; inactive on steady films, with
  /// continuous pulses or an unbounded horizon.
  struct WindowGate {
    bool active = false;
    bool dropBefore = false;    // skip what lands before the window (else weigh it by beforeWeight)
    double beforeWeight = 1.0;
    double windowStart = 0.0;   // a deposit ending before windowStart - late lands before the window
    double late = 0.0;          // the latest pulse's end plus the time filter's reach
    /// True when a deposit over an OPL range ending at `end` lands wholly before the window.
    bool before(double end) const { return active && end + late < windowStart; }
  };
  WindowGate windowGate(const Scene& scene, RadianceRecorder& recorder, Sampler& sampler) const;
  // The estimates along the way.
  /// The beams along the current segment: from the path's vertex, `tMax`
  /// along unit `direction` (toward the surface point it ends on, if any).
  void gatherBeams(const Scene& scene, const Path& path, const Vec3f& direction, float tMax, Sampler& sampler,
                   RadianceRecorder& recorder);
  void nextEvent(const Scene& scene, const Path& path, const SurfaceInteraction& si, Sampler& sampler,
                 RadianceRecorder& recorder);
  void gatherSurfacePhotons(const Scene& scene, const Path& path, const SurfaceInteraction& si, Sampler& sampler,
                            RadianceRecorder& recorder);

  const BeamSettings& settings_;
  const PassMaps& maps_;
  std::vector<uint32_t>& scratch_;
  BeamMap::VisitMarks& marks_;
  CameraStatistics& stats_;
  mutable double latestPulse_ = std::numeric_limits<double>::quiet_NaN();  // windowGate: the latest pulse's end
};

}  // namespace femto::beams
