#pragma once
// Next-event estimation towards an emitting shape: a point sampled uniformly
// by area, its density converted to solid angle at the receiving point. One
// function for every area-like emitter (area, angulararea).
#include <cmath>

#include <femto/render/emitter.h>
#include <femto/render/shape.h>

namespace femto {

/// Area density 1/A times the Jacobian dist^2 / cos(theta_light) of the
/// area-to-solid-angle change of measure (Veach 1997, eq. 8.10); zero when
/// the reference point sees the back of the emitter, which emits nothing.
inline float shapeDirectionPdf(const Shape& shape, const DirectionSample& ds) {
  float cosLight = -dot(ds.n, ds.d);
  if (cosLight <= 0.0f) return 0.0f;
  return ds.dist * ds.dist / (cosLight * shape.surfaceArea());
}

/// Fills `ds` towards a uniform point of `shape`; false (and ds.pdf = 0) when
/// the sample cannot contribute (coincident points, back side, degenerate pdf).
inline bool sampleShapeDirection(const Shape& shape, const Point3f& ref, const Point2f& u, DirectionSample& ds) {
  ds = DirectionSample();
  PositionSample ps = shape.samplePosition(u);
  Vec3f toLight = ps.p - ref;
  float dist2 = squaredLength(toLight);
  if (!(dist2 > 0.0f)) return false;
  ds.p = ps.p;
  ds.n = ps.n;
  ds.dist = std::sqrt(dist2);
  ds.d = toLight / ds.dist;
  ds.pdf = shapeDirectionPdf(shape, ds);
  if (!(ds.pdf > 0.0f) || !std::isfinite(ds.pdf)) {
    ds.pdf = 0.0f;
    return false;
  }
  return true;
}

}  // namespace femto
