#pragma once
// Shared by the ray x beam tests: pairs built from their closest-approach
// geometry (randomly rotated, so no test relies on axis-aligned rounding) and
// a brute-force reference that only asks "is this point inside the beam's
// kernel region?" along the camera segment, in double.
#include <algorithm>
#include <cmath>
#include <limits>

#include <femto/math/pcg32.h>
#include <transient_beams/ray_beam.h>

namespace femto::beams::test {

struct Vec3d {
  double x = 0, y = 0, z = 0;
};
inline Vec3d toD(const Vec3f& v) { return {v.x, v.y, v.z}; }
inline Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3d operator*(Vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dotD(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// A rotation (orthonormal frame) from a random unit quaternion.
struct Rotation {
  double m[3][3];
  explicit Rotation(PCG32& rng) {
    double q[4], n = 0;
    do {
      n = 0;
      for (double& c : q) c = 2 * rng.nextDouble() - 1, n += c * c;
    } while (n > 1 || n < 1e-3);
    n = std::sqrt(n);
    double w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    std::copy(&r[0][0], &r[0][0] + 9, &m[0][0]);
  }
  Vec3d operator()(Vec3d v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
};

inline Vec3f toF(Vec3d v) { return {float(v.x), float(v.y), float(v.z)}; }

/// How a pair is laid out in its own frame: the beam runs along +x from
/// x = -sClosest; the camera direction makes angle `theta` with it in the xy
/// plane; the lines come closest at the beam's parameter `sClosest` and the
/// ray's `tClosest`, `offset` apart along z (the common normal); `shift`
/// moves the beam within the plane perpendicular to it (y, z) on top.
struct PairSpec {
  double theta = 1.0;
  double sClosest = 1.0, tClosest = 1.0;
  double length = 2.0, tMax = 2.0;
  double offset = 0.0;
  double shiftY = 0.0;
  float etaCamera = 1.0f, etaBeam = 1.0f;
};

struct Pair {
  CameraSegment segment;
  Beam beam;
};

/// The pair of `spec`, rotated by `rot` and translated by `origin`.
inline Pair makePair(const PairSpec& spec, const Rotation& rot, Vec3d origin = {}) {
  Vec3d v{1, 0, 0}, w{std::cos(spec.theta), std::sin(spec.theta), 0};
  Vec3d beamStart{-spec.sClosest, spec.shiftY, spec.offset};
  Vec3d camera = w * (-spec.tClosest);  // the ray passes the origin at tClosest
  Pair p;
  p.beam.origin = toF(rot(beamStart) + origin);
  p.beam.direction = toF(rot(v));
  p.beam.length = float(spec.length);
  p.beam.eta = spec.etaBeam;
  p.segment.ray = Ray(toF(rot(camera) + origin), toF(rot(w)));
  p.segment.tMax = float(spec.tMax);
  p.segment.eta = spec.etaCamera;
  return p;
}

/// What a brute-force march along the camera segment finds inside the
/// kernel region (finite cylinder of radius r between the beam's end planes).
struct Overlap {
  double length = 0.0;                                    // measure of the inside part of [0, tMax]
  double tFirst = std::numeric_limits<double>::infinity();  // first / last inside sample
  double tLast = -std::numeric_limits<double>::infinity();
  double oplMin = std::numeric_limits<double>::infinity();  // OPL extremes over the inside samples
  double oplMax = -std::numeric_limits<double>::infinity();
  double step = 0.0;                                      // march step: the reference's resolution
  // The causal OPL g(t) = eta_c t + eta_b |x(t) - beam start| (ray_beam.cpp):
  // at the first and last inside samples, and its minimum over them.
  double causalFirst = 0.0, causalLast = 0.0;
  double causalMin = std::numeric_limits<double>::infinity();
};

inline bool insideKernel(const Pair& p, float radius, double t, double* sOut = nullptr, double* gapOut = nullptr) {
  Vec3d x = toD(p.segment.ray.o) + toD(p.segment.ray.d) * t;
  Vec3d v = toD(p.beam.direction);
  Vec3d rel = x - toD(p.beam.origin);
  double s = dotD(rel, v);
  Vec3d perp = rel - v * s;
  if (sOut) *sOut = s;
  if (gapOut) *gapOut = std::sqrt(dotD(perp, perp));
  return s >= 0 && s <= p.beam.length && dotD(perp, perp) < double(radius) * radius;
}

/// The OPL a real path from the beam's start to x(t) and along the camera
/// segment to its origin takes at least: eta_c t + eta_b |x(t) - start|.
inline double causalOpl(const Pair& p, double t) {
  Vec3d x = toD(p.segment.ray.o) + toD(p.segment.ray.d) * t;
  Vec3d rel = x - toD(p.beam.origin);
  return double(p.segment.eta) * t + double(p.beam.eta) * std::sqrt(dotD(rel, rel));
}

/// Midpoint march over [t0, t1] (default the whole segment) with `steps` samples.
inline Overlap marchOverlap(const Pair& p, float radius, int steps, double t0 = 0.0, double t1 = -1.0) {
  if (t1 < 0) t1 = p.segment.tMax;
  Overlap o;
  o.step = (t1 - t0) / steps;
  for (int i = 0; i < steps; ++i) {
    double t = t0 + (i + 0.5) * o.step, s = 0;
    if (!insideKernel(p, radius, t, &s)) continue;
    o.length += o.step;
    o.tFirst = std::min(o.tFirst, t);
    o.tLast = std::max(o.tLast, t);
    double opl = double(p.segment.eta) * t + double(p.beam.eta) * s;
    o.oplMin = std::min(o.oplMin, opl);
    o.oplMax = std::max(o.oplMax, opl);
    const double g = causalOpl(p, t);
    if (t == o.tFirst) o.causalFirst = g;
    o.causalLast = g;
    o.causalMin = std::min(o.causalMin, g);
  }
  return o;
}

/// True when every field of `h` is finite and consistent with the contract
/// of RayBeamHit for this pair.
inline bool hitContractHolds(const Pair& p, const RayBeamHit& h) {
  auto fin = [](double x) { return std::isfinite(x); };
  return fin(h.kernel) && h.kernel > 0 && fin(h.tRay) && fin(h.tBeam) && fin(h.oplBegin) && fin(h.oplEnd) &&
         fin(h.tRayBegin) && fin(h.tRayEnd) && h.tRayBegin >= 0 && h.tRayBegin < h.tRayEnd &&
         h.tRayEnd <= p.segment.tMax && h.tRay >= h.tRayBegin && h.tRay <= h.tRayEnd && h.tBeam >= 0 &&
         h.tBeam <= p.beam.length && h.oplBegin <= h.oplEnd;
}

}  // namespace femto::beams::test
