#pragma once
// Equiangular distance sampling (Kulla and Fajardo, "Importance Sampling
// Techniques for Path Tracing in Participating Media", EGSR 2012, sec. 4.1):
// picks the distance t along a ray segment [0, tEnd] with density
// proportional to 1 / |x(t) - c|^2 for a point c, by sampling the angle
// subtended at c uniformly. Next-event estimation from free-flight vertices
// to a point light inside a medium has infinite variance: vertices land at
// distance r from the light with probability ~ r^3, and contribute ~ 1/r^2,
// so P(contribution > V) ~ V^-3/2. A vertex chosen equiangularly cancels the
// 1/r^2; combined with free flights by MIS, the estimate stays bounded near
// the light and keeps free flights' efficiency far from it.
#include <femto/math/vector.h>

namespace femto {

/// A ray segment o + t d, t in [tStart, tEnd] (unit d; tEnd may be Infinity)
/// seen from a point `c`.
struct EquiangularSegment {
  double delta = 0.0;   // t of the point of the line closest to c
  double height = 0.0;  // distance from c to the line
  double thetaA = 0.0, thetaB = 0.0;  // angles at c of t = tStart and t = tEnd, measured from the closest point
  float tStart = 0.0f, tEnd = 0.0f;
  /// False when the segment is empty or c lies on its line (no density).
  bool valid() const { return thetaB > thetaA && height > 0.0; }
};

EquiangularSegment equiangularSegment(const Point3f& o, const Vec3f& d, float tEnd, const Point3f& c);
/// The part [tStart, tEnd] of the segment (time-gated sampling,
/// transport/time_gate.h, samples only where contributions reach the window).
EquiangularSegment equiangularSegment(const Point3f& o, const Vec3f& d, float tStart, float tEnd, const Point3f& c);
/// Distance for `u` in [0, 1), with its density; requires seg.valid().
float sampleEquiangular(const EquiangularSegment& seg, float u, float& pdf);
/// Density of sampleEquiangular at t (0 outside [tStart, tEnd] or for an invalid segment).
float pdfEquiangular(const EquiangularSegment& seg, float t);

}  // namespace femto
