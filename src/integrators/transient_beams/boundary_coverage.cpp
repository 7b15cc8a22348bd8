// The kernel's boundary loss counted on the scene (boundary_coverage.h).
#include <transient_beams/boundary_coverage.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>
#include <femto/math/frame.h>
#include <femto/render/interaction.h>
#include <femto/render/scene.h>
#include <femto/render/shape.h>
#include <femto/transport/volumetric.h>

namespace femto::beams {
namespace {

/// Index-matched surfaces of the same medium a probe crosses before giving up.
constexpr int MaxCrossings = 8;

/// Does the straight path from x to p stay in `medium` (crossing only
/// surfaces with the same medium on both sides)?
bool staysInMedium(const Scene& scene, const Point3f& x, const Point3f& p, const Medium* medium) {
  const Vec3f d = p - x;
  const float length = femto::length(d);
  if (!(length > 0.0f)) return true;
  const Vec3f dir = d / length;
  Ray ray(x, dir, 0.0f, length);
  for (int i = 0; i < MaxCrossings; ++i) {
    SurfaceInteraction si;
    if (!scene.rayIntersect(ray, si)) return true;
    if (!sameMediumAcross(si, dir, medium)) return false;
    ray = si.spawnRay(dir);
    ray.tmax = distance(ray.o, p);
  }
  return false;
}

/// Does the line from p along unit `d` (p outside `medium`) meet a boundary
/// with `medium` behind it within the extension beams get there? A shape
/// declaring media says which is behind; a solid shape (no media, not a
/// pass-through) stands in `medium` (walls in fog): beams leaving or
/// hitting it are extended into it.
bool extensionReaches(const Scene& scene, const Point3f& p, const Vec3f& d, const Medium* medium, double r) {
  const Ray ray(p, d, 0.0f, float(MaxBoundaryExtension * r));
  SurfaceInteraction si;
  if (!scene.rayIntersect(ray, si)) return false;
  if (!(double(si.t) <= double(boundaryExtension(si.n, d)) * r)) return false;
  const Shape* shape = si.shape;
  if (shape && (shape->interiorMedium() || shape->exteriorMedium())) return mediumAfter(si, d, nullptr) == medium;
  return !isPassThrough(si);
}

}  // namespace

double uncoveredShare(const Scene& scene, const Point3f& x, const Vec3f& direction, const Medium* medium, double r,
                      double turn) {
  const Frame frame(direction);
  // Equal-area rings, golden-angle spiral: an even cover of the disc.
  constexpr double GoldenTurn = 0.38196601125010515;
  int uncovered = 0;
  for (int k = 0; k < DiscPoints; ++k) {
    const double radius = r * std::sqrt((k + 0.5) / DiscPoints);
    const double angle = 2.0 * Pi * (turn + k * GoldenTurn);
    const Point3f p = x + frame.s * float(radius * std::cos(angle)) + frame.t * float(radius * std::sin(angle));
    if (staysInMedium(scene, x, p, medium)) continue;
    if (extensionReaches(scene, p, direction, medium, r) || extensionReaches(scene, p, -direction, medium, r)) continue;
    ++uncovered;
  }
  return double(uncovered) / DiscPoints;
}

std::vector<CoverageSample> coverageSamples(const std::vector<NearPair>& pairs, double r) {
  std::vector<CoverageSample> samples;
  if (pairs.empty()) return samples;
  const size_t stride = (pairs.size() + MaxCoveragePairs - 1) / MaxCoveragePairs;
  for (size_t i = 0; i < pairs.size(); i += stride) {
    const NearPair& p = pairs[i];
    RayBeamHit hit;
    const double w = pairContribution(p, r, &hit);
    if (!(w > 0.0)) continue;
    // Stratified along the pair's overlap: where its kernel puts the
    // beam's density on the probe.
    for (int k = 0; k < PointsPerPair; ++k) {
      const float t = hit.tRayBegin + (hit.tRayEnd - hit.tRayBegin) * (float(k) + 0.5f) / float(PointsPerPair);
      samples.push_back({p.probe->segment.ray(t), p.beam->direction, p.beam->medium, w / PointsPerPair});
    }
  }
  return samples;
}

double boundaryLossShare(const Scene& scene, const std::vector<CoverageSample>& samples, double r) {
  double kept = 0.0, lost = 0.0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const CoverageSample& c = samples[i];
    // A fixed turn per sample (the golden ratio's multiples): deterministic.
    const double turn = std::fmod(double(i) * 0.6180339887498949, 1.0);
    const double f = std::min(uncoveredShare(scene, c.x, c.direction, c.medium, r, turn), MaxUncovered);
    kept += c.weight, lost += c.weight * f / (1.0 - f);
  }
  return kept + lost > 0.0 ? lost / (kept + lost) : 0.0;
}

double coveredBoundaryRadius(const Scene& scene, const std::vector<Beam>& beams,
                             const std::vector<ProbeSegment>& probes, double upper) {
  if (!(upper > 0.0) || !std::isfinite(upper)) return Infinity;
  // The camera points and beam directions are sampled once, at `upper`;
  // the loss at smaller radii is counted at the same points, so that it
  // falls smoothly with r instead of with ever fewer pairs.
  const std::vector<CoverageSample> samples = coverageSamples(nearPairs(beams, probes, upper), upper);
  auto holds = [&](double r) { return boundaryLossShare(scene, samples, r) <= BoundaryBiasTarget; };
  double share = boundaryLossShare(scene, samples, upper);
  if (share <= BoundaryBiasTarget) return Infinity;
  // Shrink in proportion (the loss falls at least as fast as r) until it
  // holds, then bisect in log r between that radius and the last one that
  // did not: where curvature leaves lines uncovered the loss falls faster
  // (r^(3/2)), and the proportional step alone lands well below the need.
  double r = upper, above = upper;
  for (int i = 0; i < 8 && share > BoundaryBiasTarget; ++i) {
    above = r;
    r *= BoundaryBiasTarget / share;
    share = boundaryLossShare(scene, samples, r);
  }
  if (share > BoundaryBiasTarget) return r;
  for (int i = 0; i < 6; ++i) {
    const double mid = std::sqrt(r * above);
    (holds(mid) ? r : above) = mid;
  }
  return r;
}

}  // namespace femto::beams
