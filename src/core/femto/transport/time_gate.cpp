#include <femto/transport/time_gate.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>

namespace femto {
namespace {

/// The t >= 0 with t + |o + t d - c| = length, for |oc|^2 = r2 and
/// delta = dot(oc, d): squaring |x(t) - c| = length - t gives
/// t = (length^2 - r2) / (2 (length - delta)), valid for length >= |oc|
/// (then length - delta > 0 unless c lies ahead on the ray, where g stays
/// at length |oc| up to t = delta).
double distanceOnEllipsoid(double length, double r2, double delta) {
  if (!(length > 0.0) || !(length * length > r2)) return 0.0;
  if (length == Infinity) return Infinity;
  double denominator = 2.0 * (length - delta);
  return denominator > 0.0 ? (length * length - r2) / denominator : Infinity;
}

}  // namespace

DistanceRange distancesArrivingWithin(const Point3f& o, const Vec3f& d, const Point3f& c, double lengthA,
                                      double lengthB) {
  Vec3f oc = c - o;
  double r2 = double(dot(oc, oc)), delta = double(dot(oc, d));
  DistanceRange range;
  range.t0 = distanceOnEllipsoid(lengthA, r2, delta);
  range.t1 = distanceOnEllipsoid(lengthB, r2, delta);
  return range;
}

}  // namespace femto
