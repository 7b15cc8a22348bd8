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
#include <femto/math/constants.h>
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

}  // namespace femto
