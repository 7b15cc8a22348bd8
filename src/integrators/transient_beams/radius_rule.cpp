// The derived beam radius's three bounds (radius_rule.h, docs/design/photon-beams.md).
#include <transient_beams/radius_rule.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <femto/math/constants.h>
#include <femto/render/medium.h>
#include <transient_beams/beam_roulette.h>
#include <transient_beams/ray_beam.h>

namespace femto::beams {
namespace {

struct V3 {
  double x, y, z;
};
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 v3(const Vec3f& v) { return {v.x, v.y, v.z}; }

}  // namespace

double segmentDistance(const Point3f& p0, const Vec3f& d0, float len0, const Point3f& p1, const Vec3f& d1, float len1,
                       double* along0) {
  // Closest points of two segments: minimise |r + u e0 - v e1|^2 over the
  // unit square (u, v), clamping one parameter and re-solving the other.
  const V3 e0 = v3(d0) * double(len0), e1 = v3(d1) * double(len1), r = v3(p0) - v3(p1);
  const double a = dot(e0, e0), e = dot(e1, e1), f = dot(e1, r);
  double u = 0.0, v = 0.0;
  if (a > 0.0 || e > 0.0) {
    if (!(a > 0.0)) {
      v = std::clamp(f / e, 0.0, 1.0);
    } else {
      const double c = dot(e0, r);
      if (!(e > 0.0)) {
        u = std::clamp(-c / a, 0.0, 1.0);
      } else {
        const double b = dot(e0, e1), denom = a * e - b * b;
        // Parallel segments (denominator at rounding level): any u; take 0.
        u = denom > 1e-12 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
        v = (b * u + f) / e;
        if (v < 0.0) {
          v = 0.0, u = std::clamp(-c / a, 0.0, 1.0);
        } else if (v > 1.0) {
          v = 1.0, u = std::clamp((b - c) / a, 0.0, 1.0);
        }
      }
    }
  }
  const V3 gap = r + e0 * u - e1 * v;
  if (along0) *along0 = u * double(len0);
  return std::sqrt(dot(gap, gap));
}

double densityRadius(const std::vector<Beam>& beams, const std::vector<ProbeSegment>& probes, double targetPairs,
                     float gatherRoulette) {
  if (probes.empty() || beams.empty()) return Infinity;
  // Every stride-th beam: each found one stands for `stride` beams.
  const size_t budget = std::max<size_t>(1, MaxDistancePairs / probes.size());
  const size_t stride = (beams.size() + budget - 1) / budget;
  // (distance, chance that a gather reaches the pair)
  std::vector<std::pair<double, double>> pairs;
  pairs.reserve(probes.size() * std::min(beams.size(), budget));
  bool weighted = false;
  for (const ProbeSegment& p : probes) {
    const BeamRoulette roulette =
        p.medium && gatherRoulette > 0.0f ? BeamRoulette::of(*p.medium, gatherRoulette) : BeamRoulette();
    const bool reachesRoulette = p.segment.tMax > roulette.start();
    weighted = weighted || reachesRoulette;
    for (size_t i = 0; i < beams.size(); i += stride) {
      const Beam& b = beams[i];
      if (b.medium != p.medium) continue;
      double along = 0.0;
      const double d = segmentDistance(p.segment.ray.o, p.segment.ray.d, p.segment.tMax, b.origin, b.direction,
                                       b.length, reachesRoulette ? &along : nullptr);
      pairs.emplace_back(d, reachesRoulette ? double(roulette.survival(float(along))) : 1.0);
    }
  }
  // Mean pairs per probe at radius r: sum of the weights of {distances < r} x stride / probes.
  const double needed = targetPairs * double(probes.size()) / double(stride);
  if (!weighted) {
    // Every weight 1: the k-th smallest distance, without a sort.
    const size_t k = size_t(std::ceil(needed));
    if (k == 0 || k > pairs.size()) return Infinity;
    std::nth_element(pairs.begin(), pairs.begin() + ptrdiff_t(k - 1), pairs.end());
    return pairs[k - 1].first;
  }
  if (!(needed > 0.0)) return Infinity;
  std::sort(pairs.begin(), pairs.end());
  double sum = 0.0;
  for (const auto& [distance, weight] : pairs)
    if ((sum += weight) >= needed) return distance;
  return Infinity;
}

std::vector<NearPair> nearPairs(const std::vector<Beam>& beams, const std::vector<ProbeSegment>& probes, double within,
                                size_t maxEvaluations) {
  std::vector<NearPair> pairs;
  if (probes.empty() || beams.empty()) return pairs;
  const size_t budget = std::max<size_t>(1, maxEvaluations / probes.size());
  const size_t stride = (beams.size() + budget - 1) / budget;
  for (const ProbeSegment& p : probes)
    for (size_t i = 0; i < beams.size(); i += stride) {
      const Beam& b = beams[i];
      if (b.medium != p.medium) continue;
      // The lines' distance bounds the segments' from below (whatever the
      // directions' lengths): most pairs end here, before segmentDistance's
      // clamped solve. Not for lines within 1e-4 rad of parallel (n is
      // rounding there); the 1e-9 margin covers the rounding of the rest.
      const V3 n = cross(v3(p.segment.ray.d), v3(b.direction));
      const double n2 = dot(n, n), along = dot(v3(p.segment.ray.o) - v3(b.origin), n);
      if (n2 > 1e-8 && along * along > within * within * n2 * (1.0 + 1e-9)) continue;
      const double d =
          segmentDistance(p.segment.ray.o, p.segment.ray.d, p.segment.tMax, b.origin, b.direction, b.length);
      if (d < within) pairs.push_back({&p, &b, d});
    }
  return pairs;
}

double pairContribution(const NearPair& pair, double r, RayBeamHit* hitOut) {
  RayBeamHit hit;
  if (!rayBeamIntersect(pair.probe->segment, *pair.beam, float(r), hit)) return 0.0;
  const double sigma = pair.beam->medium ? double(pair.beam->medium->majorant().average()) : 0.0;
  const double w = double(hit.kernel) * double(pair.beam->power.average()) *
                   std::exp(-sigma * (double(hit.tRay) + double(hit.tBeam)));
  if (!(w > 0.0) || !std::isfinite(w)) return 0.0;
  if (hitOut) *hitOut = hit;
  return w;
}

double timeRadius(const TimeGrid& grid, double eta) {
  if (!grid.isTransient() || !(grid.binWidth > 0.0) || !(eta > 0.0)) return Infinity;
  // A pair crossing the beam's axis perpendicularly covers a chord 2r, OPL
  // 2 eta r (ray_beam.h): at most TimeBinFraction bins.
  return TimeBinFraction * grid.binWidth / (2.0 * eta);
}

double obliqueTimeRadius(const std::vector<Beam>& beams, const std::vector<ProbeSegment>& probes, const TimeGrid& grid,
                         double eta, double upper) {
  const double perpendicular = timeRadius(grid, eta);
  // No bins (a steady film): no time bound at all. (Below, a steady grid's
  // default bin width of 1 would bound scenes in large units.)
  if (!std::isfinite(perpendicular)) return perpendicular;
  const double hi = std::min(upper, perpendicular);
  if (!(hi > 0.0) || probes.empty() || beams.empty()) return perpendicular;
  const std::vector<NearPair> pairs = nearPairs(beams, probes, hi);
  // E[W^2] at radius r over the pairs' expected contributions.
  auto meanSquare = [&](double r) {
    double sum = 0.0, weights = 0.0;
    for (const NearPair& p : pairs) {
      if (!(p.distance < r)) continue;
      RayBeamHit hit;
      const double w = pairContribution(p, r, &hit);
      if (!(w > 0.0)) continue;
      const double width = hit.oplEnd - hit.oplBegin;
      sum += w * width * width, weights += w;
    }
    return weights > 0.0 ? sum / weights : 0.0;
  };
  // A perpendicular pair at the perpendicular bound: W = 2 eta r sqrt(1 -
  // (d/r)^2), E_d[W^2] = (8/3) eta^2 r^2 = (2/3) (K bins)^2.
  const double allowed = (2.0 / 3.0) * std::pow(TimeBinFraction * grid.binWidth, 2);
  if (meanSquare(hi) <= allowed) return perpendicular;
  // E[W^2] grows with r (about as r^2, slower where chords are clipped):
  // bisection in log r.
  double lo = hi * 1e-3, up = hi;
  if (meanSquare(lo) > allowed) return lo;
  for (int i = 0; i < 30; ++i) {
    const double mid = std::sqrt(lo * up);
    (meanSquare(mid) <= allowed ? lo : up) = mid;
  }
  return lo;
}

double boundaryRadius(const std::vector<ProbeSegment>& probes, bool extended) {
  double length = 0.0;
  for (const ProbeSegment& p : probes) length += double(p.segment.tMax);
  if (probes.empty() || !(length > 0.0)) return Infinity;
  const double mean = length / double(probes.size());
  // Relative loss ~ BoundaryLossPerRadius r / mean: at most BoundaryBiasTarget.
  return BoundaryBiasTarget * mean / (BoundaryLossPerRadius * (extended ? BoundaryLossLeft : 1.0));
}

}  // namespace femto::beams
