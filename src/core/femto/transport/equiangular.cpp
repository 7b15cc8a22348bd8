#include <femto/transport/equiangular.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>

namespace femto {

EquiangularSegment equiangularSegment(const Point3f& o, const Vec3f& d, float tEnd, const Point3f& c) {
  return equiangularSegment(o, d, 0.0f, tEnd, c);
}

EquiangularSegment equiangularSegment(const Point3f& o, const Vec3f& d, float tStart, float tEnd, const Point3f& c) {
  EquiangularSegment seg;
  Vec3f oc = c - o;
  seg.delta = double(dot(oc, d));
  double r2 = double(dot(oc, oc));
  seg.height = std::sqrt(std::max(0.0, r2 - seg.delta * seg.delta));
  seg.tStart = tStart;
  seg.tEnd = tEnd;
  // A light on the ray's line (height ~ 0 relative to its distance) has no usable angle.
  if (!(seg.height > 1e-7 * std::sqrt(r2)) || !(tEnd > tStart) || !(tStart >= 0.0f)) return EquiangularSegment();
  seg.thetaA = std::atan2(double(tStart) - seg.delta, seg.height);
  seg.thetaB = std::isfinite(tEnd) ? std::atan2(double(tEnd) - seg.delta, seg.height) : std::atan2(1.0, 0.0);  // pi / 2 in double
  return seg;
}

float sampleEquiangular(const EquiangularSegment& seg, float u, float& pdf) {
  double theta = seg.thetaA + double(u) * (seg.thetaB - seg.thetaA);
  double t = seg.delta + seg.height * std::tan(theta);
  t = std::clamp(t, double(seg.tStart), double(seg.tEnd));
  pdf = pdfEquiangular(seg, float(t));
  return float(t);
}

float pdfEquiangular(const EquiangularSegment& seg, float t) {
  if (!seg.valid() || !(t >= seg.tStart) || !(t <= seg.tEnd)) return 0.0f;
  double x = double(t) - seg.delta;
  return float(seg.height / ((seg.thetaB - seg.thetaA) * (seg.height * seg.height + x * x)));
}

}  // namespace femto
