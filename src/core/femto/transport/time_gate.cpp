#include <femto/transport/time_gate.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>

namespace femto {

double distanceReaching(const Point3f& o, const Vec3f& d, const Point3f& c, double eta, double length) {
  Vec3f oc = c - o;
  double r2 = double(dot(oc, oc)), delta = double(dot(oc, d));
  if (!(length > 0.0) || !(length * length > r2)) return 0.0;
  if (length == Infinity) return Infinity;
  // Squaring |x(t) - c| = length - eta t: A t^2 - 2 B t + C = 0 with
  // A = eta^2 - 1, B = eta length - delta (> 0: length > |oc| >= delta),
  // C = length^2 - |oc|^2 (> 0). The smaller root is the one with
  // length - eta t >= 0 (the other solves eta t - |x(t) - c| = length), in
  // the form that stays exact for A = 0: eta = 1 gives t = C / (2 B), the
  // ellipsoid with foci o and c (distancesArrivingWithin).
  double a = eta * eta - 1.0, b = eta * length - delta, cc = length * length - r2;
  double denominator = b + std::sqrt(std::max(0.0, b * b - a * cc));
  return denominator > 0.0 ? cc / denominator : Infinity;
}

DistanceRange distancesArrivingWithin(const Point3f& o, const Vec3f& d, const Point3f& c, double lengthA,
                                      double lengthB) {
  // t + |x(t) - c| = length: the ellipsoid with foci o and c, distanceReaching at eta = 1.
  DistanceRange range;
  range.t0 = distanceReaching(o, d, c, 1.0, lengthA);
  range.t1 = distanceReaching(o, d, c, 1.0, lengthB);
  return range;
}

float LightBound::distanceFrom(const Point3f& p) const {
  if (anywhere) return 0.0f;
  float nearest = Infinity;
  for (int k = 0; k < count; ++k) nearest = std::min(nearest, distance(p, points[k]));
  return nearest;
}

double gateReach(const Ray& ray, double eta, double startOpl, const OplGate& gate, const LightBound& lights) {
  if (!(gate.end < Infinity) || !std::isfinite(startOpl) || !(eta >= 1.0)) return Infinity;
  double length = gate.end - startOpl;
  if (!(length > 0.0)) return 0.0;
  if (lights.anywhere) return length / eta;
  // A vertex may still contribute when some light is close enough: the
  // farthest such distance over the lights.
  double reach = 0.0;
  for (int k = 0; k < lights.count; ++k)
    reach = std::max(reach, distanceReaching(ray.o, ray.d, lights.points[k], eta, length));
  return reach;
}

float longestDetour(const Point3f& x, const BoundingBox3f& box, const Point3f& c) {
  float longest = 0.0f;
  for (int k = 0; k < 8; ++k) {
    Point3f corner(k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z);
    longest = std::max(longest, distance(x, corner) + distance(corner, c));
  }
  return longest;
}

}  // namespace femto
