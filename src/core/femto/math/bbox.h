#pragma once
#include <femto/math/constants.h>
#include <femto/math/vector.h>

namespace femto {

/// Axis-aligned bounding box; starts empty (min = +inf, max = -inf).
struct BoundingBox3f {
  Point3f min{Infinity}, max{-Infinity};

  BoundingBox3f() = default;
  BoundingBox3f(const Point3f& a, const Point3f& b) : min(femto::min(a, b)), max(femto::max(a, b)) {}
  bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
  void expand(const Point3f& p) { min = femto::min(min, p); max = femto::max(max, p); }
  void expand(const BoundingBox3f& b) { min = femto::min(min, b.min); max = femto::max(max, b.max); }
  Point3f center() const { return (min + max) * 0.5f; }
  Vec3f extents() const { return max - min; }
  bool contains(const Point3f& p) const {
    return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z && p.z <= max.z;
  }
  /// Radius of the bounding sphere centred at center().
  float boundingRadius() const { return valid() ? length(max - min) * 0.5f : 0.0f; }
};

}  // namespace femto
