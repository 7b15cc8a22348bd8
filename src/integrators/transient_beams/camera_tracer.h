#pragma once
// The camera side of transient photon beams (Marco et al. 2017, sec. 4), per
// thread: one camera sample against one pass's photon maps.
//
// A camera path follows index-matched boundaries and specular chains (mirrors,
// glass) and ends at the first surface with a non-specular BSDF. Along the
// way every piece inside a medium gathers the beams passing within the
// kernel radius (rayBeamIntersect): each pair adds
//
//   throughput sigma_s(x) f_p(-ray.d, -beam.d) T_cam(tRay) T_beam(tBeam) Phi kernel / N
//
// spread over the pair's OPL interval (camera OPL + beam OPL + overlap), N the
// photons traced in the pass. The camera ray itself is only attenuated in
// media (T_cam to the surface), never scattered: medium radiance comes from
// the beams alone. At the final surface, direct light comes from next-event
// estimation (through media, with its OPL) and indirect light and caustics
// from the surface photons within the surface radius (uniform disc kernel,
// Jensen 2001 eq. 7.6), deposited at photon OPL + camera OPL. Emitters seen
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

/// What one pass gives the camera side (all immutable, shared by threads).
struct PassMaps {
  const BeamMap& beams;
  const SurfacePhotonMap& photons;
  float beamRadius = 0.0f;
  float surfaceRadius = 0.0f;
  uint64_t photonCount = 1;  // photons traced in the pass (the estimates' N)
};

class CameraTracer {
 public:
  /// `scratch` holds query results between calls (one per thread).
  CameraTracer(const BeamSettings& settings, const PassMaps& maps, std::vector<uint32_t>& scratch)
      : settings_(settings), maps_(maps), scratch_(scratch) {}

  /// Trace one camera sample along `ray` (OPL 0 at the sensor).
  void sample(const Scene& scene, const Ray& ray, Sampler& sampler, RadianceRecorder& recorder);

 private:
  struct Path;
  void gatherBeams(const Scene& scene, const Path& path, float tMax, Sampler& sampler, RadianceRecorder& recorder);
  void nextEvent(const Scene& scene, const Path& path, const SurfaceInteraction& si, Sampler& sampler,
                 RadianceRecorder& recorder);
  void gatherSurfacePhotons(const Scene& scene, const Path& path, const SurfaceInteraction& si,
                            RadianceRecorder& recorder);

  const BeamSettings& settings_;
  const PassMaps& maps_;
  std::vector<uint32_t>& scratch_;
};

}  // namespace femto::beams
