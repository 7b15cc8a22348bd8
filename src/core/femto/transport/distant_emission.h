#pragma once
// What emitters at infinity (directional, constant, envmap) share: the
// sphere bounding the scene, and rays that enter it from a given direction.
// A distant emitter lights the scene like a beam as wide as that sphere, so
// an emitted ray starts on the disk of radius R facing the beam, one radius
// before the centre, and its power is the irradiance times the disk's area
// (Pharr, Jakob and Humphreys, PBR 3rd ed., sec. 16.1.5).
#include <femto/math/ray.h>
#include <femto/math/vector.h>
#include <femto/render/emitter.h>

namespace femto {

class Scene;

struct SceneSphere {
  Point3f center;
  float radius = 1.0f;

  /// The bounding sphere of the scene's shapes; a unit sphere at the origin
  /// for a scene without shapes (so emitted rays stay well defined).
  static SceneSphere of(const Scene& scene);
  /// Area of the disk emitted rays start from: pi R^2.
  float diskArea() const;
  /// A ray travelling along unit direction `d`, starting uniformly (area
  /// density 1 / diskArea()) on the disk of radius R perpendicular to `d`
  /// centred at center - R d. Every such ray crosses the scene's bounds region.
  Ray rayAlong(const Vec3f& d, const Point2f& u) const;
  /// A point along `d` from `ref` outside the scene's sphere, to stand for
  /// "the emitter" in a DirectionSample (whose dist is Infinity).
  Point3f pointAtInfinity(const Point3f& ref, const Vec3f& d) const;
  /// A DirectionSample for light arriving at `ref` from unit direction `d`
  /// (toward the emitter): dist = Infinity, p = pointAtInfinity, n = -d.
  /// pdf and delta are left for the emitter to fill in.
  DirectionSample directionSample(const Point3f& ref, const Vec3f& d) const;
};

}  // namespace femto
