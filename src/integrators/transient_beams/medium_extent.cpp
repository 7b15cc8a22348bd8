#include <transient_beams/medium_extent.h>

#include <algorithm>
#include <cmath>

#include <femto/render/medium.h>
#include <femto/render/scene.h>

namespace femto::beams {
namespace {
/// Surfaces skipped before the probe gives up and answers the sensor's medium.
constexpr int MaxProbeHits = 64;
/// Optical depth beyond which a homogeneous medium's transmittance (e^-40) is negligible.
constexpr float NegligibleOpticalDepth = 40.0f;
}  // namespace

const Medium* mediumAround(const Scene& scene, const Ray& start) {
  Ray ray(start.o, start.d);
  for (int i = 0; i < MaxProbeHits; ++i) {
    SurfaceInteraction si;
    if (!scene.rayIntersect(ray, si)) break;
    const Medium* inside = si.shape->interiorMedium();
    const Medium* outside = si.shape->exteriorMedium();
    if (inside || outside) return dot(ray.d, si.n) < 0.0f ? outside : inside;  // the side the ray arrived from
    ray = si.spawnRay(ray.d);
  }
  return scene.sensor().medium();
}

float unboundedSegmentLength(const Medium& medium, double opl, double horizon) {
  float length = Infinity;
  if (std::isfinite(horizon) && medium.eta() > 0.0f) length = float(std::max(0.0, (horizon - opl) / medium.eta()));
  if (medium.isHomogeneous()) {
    Color3f sigmaT = medium.majorant();
    float minSigmaT = std::min(sigmaT.r, std::min(sigmaT.g, sigmaT.b));
    if (minSigmaT > 0.0f) length = std::min(length, NegligibleOpticalDepth / minSigmaT);
  }
  return std::isfinite(length) ? length : 0.0f;
}

}  // namespace femto::beams
