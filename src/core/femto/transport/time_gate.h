#pragma once
// Time-gated distance ranges (temporal importance sampling): which distances
// along a ray segment put a vertex whose connection to a point light arrives
// inside the film's time window. A vertex at distance t along o + t d,
// connected to a light at c, closes a path of length g(t) = t + |o + t d - c|
// from o: g increases with t (g' = 1 + cos >= 0), and the points with
// g(t) = L lie on the ellipsoid with foci o and c. So the distances whose
// contributions arrive in a window of path lengths [lengthA, lengthB) form one
// interval [t(lengthA), t(lengthB)), in closed form (Jarabo et al., "A
// Framework for Transient Rendering", SIGGRAPH Asia 2014, sec. 6; He et al.,
// "DARTS", SIGGRAPH Asia 2024, sample distances on this interval).
#include <array>

#include <femto/math/bbox.h>
#include <femto/math/constants.h>
#include <femto/math/ray.h>
#include <femto/math/vector.h>

namespace femto {

/// Path lengths from o + t d to c, plus t, that land in a time window: the
/// distances t in [t0, t1) (both may be 0 or Infinity).
struct DistanceRange {
  double t0 = 0.0, t1 = 0.0;
  bool empty() const { return !(t1 > t0); }
};

/// Distances t >= 0 along the ray o + t d (unit d) with t + |o + t d - c| in
/// [lengthA, lengthB): a vertex there, connected straight to c, closes a path
/// of length in the window. Lengths below |o - c| give t = 0.
DistanceRange distancesArrivingWithin(const Point3f& o, const Vec3f& d, const Point3f& c, double lengthA,
                                      double lengthB);

/// The OPL window a contribution must reach to land in a transient film:
/// [start, end), or everything (-Infinity, Infinity) for steady films.
struct OplGate {
  double start = -Infinity, end = Infinity;
  bool gates() const { return start > -Infinity || end < Infinity; }
};

/// Distance t >= 0 along o + t d (unit d) where eta * t + |o + t d - c|
/// reaches `length` (eta >= 1): the segment's OPL at refractive index eta plus
/// a straight leg to c at index >= 1. The sum grows with t (its derivative is
/// eta + cos >= 0), so every t beyond this one gives at least `length`. 0 when
/// |o - c| >= length already; Infinity for an infinite length (or eta = 1
/// with c ahead on the ray, where the sum stays |o - c|).
double distanceReaching(const Point3f& o, const Vec3f& d, const Point3f& c, double eta, double length);

/// Where the light a path may still reach can be, for residual-time
/// truncation (time gating of free flights): the points of point lights, or
/// anywhere when some emitter is not at a point (area, environment,
/// directional: their light may be recorded at the vertex's own OPL) or there
/// are more than the few points kept.
struct LightBound {
  static constexpr int MaxPoints = 4;
  std::array<Point3f, MaxPoints> points;
  int count = 0;
  bool anywhere = true;
  /// A lower bound of the distance from `p` to any light.
  float distanceFrom(const Point3f& p) const;
};

/// Residual-time truncation: the distance along `ray` (from OPL `startOpl`,
/// in a medium of refractive index `eta`, or none: eta = the surface's)
/// beyond which a vertex cannot contribute before gate.end: from there even
/// the straight connection to the nearest light arrives at or after the end
/// (every later contribution is at least that long: triangle inequality,
/// refractive indices >= 1, scattering delays only add). Infinity when the
/// gate has no end, the OPL is not counted (startOpl = -Infinity: the camera
/// segment without observer time) or eta < 1.
double gateReach(const Ray& ray, double eta, double startOpl, const OplGate& gate, const LightBound& lights);

/// Whether a vertex at `p` with OPL `opl` can no longer contribute before
/// gate.end (the same bound at a single point).
inline bool pastGate(const Point3f& p, double opl, const OplGate& gate, const LightBound& lights) {
  return gate.end < Infinity && opl + double(lights.distanceFrom(p)) >= gate.end;
}

/// The longest |x - y| + |y - c| over the points y of `box` (valid): the
/// sum is convex in y, so it is largest at a corner. A bound of the length of
/// any path from x through the box to c.
float longestDetour(const Point3f& x, const BoundingBox3f& box, const Point3f& c);

}  // namespace femto
