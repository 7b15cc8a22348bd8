#pragma once
// Intersecting one analytic shape on its own, without a scene, and filling
// the interaction as the core does: for the shape tests.
#include <femto/render/shape.h>

namespace femto::test {

/// The nearest hit of `ray` on `shape` in (tmin, tmax), with `si` filled
/// (si.t included); false on a miss.
inline bool hit(const Shape& shape, const Ray& ray, SurfaceInteraction& si) {
  float t;
  Point2f uv;
  if (!shape.intersect(ray, t, uv)) return false;
  shape.computeInteraction(ray, t, 0, uv, si);
  si.t = t;
  return true;
}

}  // namespace femto::test
