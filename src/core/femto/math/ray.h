#pragma once
#include <femto/math/constants.h>
#include <femto/math/vector.h>

namespace femto {

/// A ray segment o + t d for t in [tmin, tmax]. `d` need not be unit length,
/// but every ray the renderer traces has a unit direction.
struct Ray {
  Point3f o;
  Vec3f d{0, 0, 1};
  float tmin = 0.0f;
  float tmax = Infinity;

  Ray() = default;
  Ray(const Point3f& o_, const Vec3f& d_, float tmin_ = 0.0f, float tmax_ = Infinity)
      : o(o_), d(d_), tmin(tmin_), tmax(tmax_) {}
  Point3f operator()(float t) const { return o + d * t; }
};

}  // namespace femto
