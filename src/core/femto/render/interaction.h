#pragma once
// What a ray hit: position, normals, shading frame, uv and the shape.
#include <cstdint>

#include <femto/math/constants.h>
#include <femto/math/frame.h>
#include <femto/math/ray.h>
#include <femto/math/spectrum.h>

namespace femto {

class Shape;
class BSDF;
class Emitter;

/// The nearest hit of a ray before its interaction is computed (Mitsuba 3's
/// PreliminaryIntersection): the distance and what Scene::computeInteraction
/// needs to fill a SurfaceInteraction later. A path in a medium needs the
/// surface only when its free flight reaches it; computing every hit's
/// shading frame was 13-17 % of transient_path's time in the fog box.
struct PreliminaryHit {
  float t = Infinity;
  const Shape* shape = nullptr;  // the shape hit (of an instanced group: the group's own shape)
  uint32_t instanceId = ~0u;     // the instance hit, ~0u for none
  uint32_t primIndex = 0;
  Point2f uv;
};

struct SurfaceInteraction {
  float t = Infinity;
  Point3f p;
  Normal3f n;        // geometric normal, world space, unit length
  Frame sh;          // shading frame, world space; sh.n is the shading normal
  Point2f uv;
  Vec3f wi;          // direction back toward the ray origin, in the local shading frame
  const Shape* shape = nullptr;
  uint32_t primIndex = 0;

  bool isValid() const { return shape != nullptr; }
  Vec3f toWorld(const Vec3f& v) const { return sh.toWorld(v); }
  Vec3f toLocal(const Vec3f& v) const { return sh.toLocal(v); }

  const BSDF* bsdf() const;
  const Emitter* emitter() const;
  /// Radiance emitted from this point toward world direction `w` (zero unless the shape is an emitter).
  Color3f Le(const Vec3f& w) const;

  /// A ray leaving this point in world direction `d`, offset off the surface
  /// on the side `d` points to (avoids self-intersection).
  Ray spawnRay(const Vec3f& d) const;
  /// A ray from this point toward `target`, stopping just short of it.
  Ray spawnRayTo(const Point3f& target) const;
  /// Offset origin for leaving the surface along `d`.
  Point3f offsetOrigin(const Vec3f& d) const;
};

}  // namespace femto
