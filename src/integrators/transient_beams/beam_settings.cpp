#include <transient_beams/beam_settings.h>

#include <cmath>
#include <string>

#include <femto/math/constants.h>

namespace femto::beams {
namespace {

/// Default radii as fractions of the scene's bounding-box diagonal: small
/// enough that the kernel blur stays below a pixel's footprint in typical
/// views, large enough for ~1e5 photons to give a usable first pass.
constexpr float kBeamRadiusFraction = 0.005f, kSurfaceRadiusFraction = 0.01f;
/// Upper bound of the derived beam radius, as a fraction of the diagonal.
constexpr float kMaxBeamRadiusFraction = 0.01f;

/// Product over passes 0..pass-1 of (i + alpha) / (i + 1).
double reduction(float alpha, int pass) {
  double f = 1.0;
  for (int i = 0; i < pass; ++i) f *= (double(i) + alpha) / double(i + 1);
  return f;
}

}  // namespace

BeamSettings BeamSettings::parse(const Properties& props) {
  BeamSettings s;
  s.location = props.location();
  int64_t passes = props.getInt("passes", 1);
  if (passes < 1 || passes > 1000000) props.raise("passes", str("must be between 1 and 1000000, got ", passes));
  s.passes = int(passes);
  s.photonCount = props.getInt("photon_count", s.photonCount);
  if (s.photonCount < 1 || s.photonCount > (int64_t(1) << 32))
    props.raise("photon_count", str("must be between 1 and 2^32 photons per pass, got ", s.photonCount));
  // Beams cost far more per photon than surface photons (a BVH over beam
  // pieces, queried by every camera segment), and an evenly lit medium needs
  // fewer of them: by default only the first 10000 photons leave beams.
  s.beamPhotonCount = props.getInt("beam_photon_count", s.beamPhotonCount);
  if (s.beamPhotonCount < 0 || s.beamPhotonCount > (int64_t(1) << 32))
    props.raise("beam_photon_count", str("must be between 0 (all photons leave beams) and 2^32, got ",
                                         s.beamPhotonCount));
  // 0 (as when absent) asks for the default derived from the scene (resolved()).
  auto readRadius = [&](const char* name) {
    if (!props.has(name)) return 0.0f;
    float r = props.getFloat(name);
    if (!(r >= 0.0f) || !std::isfinite(r))
      props.raise(name, str("must be a finite radius > 0 (scene units), or 0 for the default derived from the "
                            "scene, got ", r));
    return r;
  };
  s.radius = readRadius("radius");
  s.surfaceRadius = readRadius("surface_radius");
  s.gatherFraction = props.getFloat("gather_fraction", s.gatherFraction);
  if (!(s.gatherFraction > 0.0f && s.gatherFraction <= 1.0f))
    props.raise("gather_fraction", str("must lie in (0, 1] (the probability that a camera segment gathers beams), got ",
                                       s.gatherFraction));
  s.alpha = props.getFloat("alpha", s.alpha);
  if (!(s.alpha > 0.0f && s.alpha <= 1.0f)) props.raise("alpha", str("must lie in (0, 1], got ", s.alpha));
  int64_t maxDepth = props.getInt("max_depth", -1);
  if (maxDepth < -1 || maxDepth > 100000) props.raise("max_depth", str("must be -1 (unbounded) or at least 0, got ", maxDepth));
  s.maxDepth = int(maxDepth);
  int64_t rrDepth = props.getInt("rr_depth", s.rrDepth);
  if (rrDepth < 1 || rrDepth > 100000) props.raise("rr_depth", str("must be at least 1, got ", rrDepth));
  s.rrDepth = int(rrDepth);
  std::string store = props.getString("store", "all");
  if (store == "all")
    s.store = BeamStore::All;
  else if (store == "single")
    s.store = BeamStore::Single;
  else
    props.raise("store", str("must be \"all\" (every scattering order) or \"single\" (single scattering), got \"",
                             store, "\""));
  std::string estimator = props.getString("volume_estimator", "beams");
  if (estimator == "beams")
    s.volumeEstimator = VolumeEstimator::Beams;
  else if (estimator == "points")
    s.volumeEstimator = VolumeEstimator::Points;
  else
    props.raise("volume_estimator", str("must be \"beams\" (photon beams, ray x beam 1D) or \"points\" (photon "
                                        "points, the beam radiance estimate), got \"", estimator, "\""));
  s.observerTime = props.getBool("observer_time", true);
  s.hideEmitters = props.getBool("hide_emitters", false);
  return s;
}

BeamSettings BeamSettings::resolved(const BoundingBox3f& sceneBounds) const {
  BeamSettings s = *this;
  if (s.radius > 0.0f && s.surfaceRadius > 0.0f) return s;
  float diagonal = 2.0f * sceneBounds.boundingRadius();
  if (!(diagonal > 0.0f) || !std::isfinite(diagonal))
    throw Error(location, "transient_beams: the scene has no finite extent to derive the kernel radii from; give "
                          "\"radius\" and \"surface_radius\"");
  if (!(s.surfaceRadius > 0.0f)) s.surfaceRadius = kSurfaceRadiusFraction * diagonal;
  return s;
}

BeamSettings BeamSettings::withBeamRadiusFrom(const std::vector<Beam>& beams, const BoundingBox3f& sceneBounds) const {
  BeamSettings s = *this;
  if (s.radius > 0.0f) return s;
  double length = 0.0;
  BoundingBox3f box;
  for (const Beam& b : beams) {
    length += b.length;
    box.expand(b.origin);
    box.expand(b.origin + b.direction * b.length);
  }
  const Vec3f e = box.valid() ? box.extents() : Vec3f(0.0f);
  const double volume = double(e.x) * double(e.y) * double(e.z);
  const float diagonal = 2.0f * sceneBounds.boundingRadius();
  const double area = std::cbrt(volume * volume);  // V^(2/3)
  double r = 0.0;
  if (volumeEstimator == VolumeEstimator::Points)
    r = volume > 0.0 && !beams.empty() ? std::sqrt(kTargetPairHits * area / (Pi * double(beams.size()))) : 0.0;
  else
    r = volume > 0.0 && length > 0.0 ? 2.0 * kTargetPairHits * area / (Pi * length) : 0.0;
  // Beams in a plane or on a line (no volume), or none: the scene's scale.
  if (!(r > 0.0) || !std::isfinite(r)) r = kBeamRadiusFraction * diagonal;
  // Never wider than the old fixed default: few photons must not blur the medium away.
  if (diagonal > 0.0f && std::isfinite(diagonal)) r = std::min(r, double(kMaxBeamRadiusFraction * diagonal));
  s.radius = float(r);
  if (!(s.radius > 0.0f) || !std::isfinite(s.radius))
    throw Error(location, "transient_beams: cannot derive a beam radius (no beams and no scene extent); give \"radius\"");
  return s;
}

float BeamSettings::beamRadius(int pass) const {
  // The 1D kernel (beams) shrinks r, the 2D kernel (points) r^2 by the factor.
  const double factor = reduction(alpha, pass);
  return float(radius * (volumeEstimator == VolumeEstimator::Points ? std::sqrt(factor) : factor));
}

float BeamSettings::surfaceRadiusOf(int pass) const { return float(surfaceRadius * std::sqrt(reduction(alpha, pass))); }

}  // namespace femto::beams
