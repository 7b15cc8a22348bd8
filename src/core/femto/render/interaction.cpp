#include <femto/render/interaction.h>

#include <femto/render/emitter.h>
#include <femto/render/shape.h>

namespace femto {

const BSDF* SurfaceInteraction::bsdf() const { return shape ? shape->bsdf() : nullptr; }

const Emitter* SurfaceInteraction::emitter() const { return shape ? shape->emitter() : nullptr; }

Color3f SurfaceInteraction::Le(const Vec3f& w) const {
  const Emitter* e = emitter();
  return e ? e->eval(*this, w) : Color3f(0.0f);
}

Point3f SurfaceInteraction::offsetOrigin(const Vec3f& d) const {
  // Floating-point error in a hit point grows with its magnitude, so the
  // offset does too (a fixed epsilon fails far from the origin). Moving along
  // the geometric normal, not along d, keeps grazing rays from re-hitting.
  float scale = RayEpsilon * (1.0f + maxComponent(abs(p)));
  Vec3f offset = n * scale;
  return dot(d, n) < 0.0f ? p - offset : p + offset;
}

Ray SurfaceInteraction::spawnRay(const Vec3f& d) const { return Ray(offsetOrigin(d), d, 0.0f, Infinity); }

Ray SurfaceInteraction::spawnRayTo(const Point3f& target) const {
  Point3f o = offsetOrigin(target - p);
  Vec3f d = target - o;
  float dist = length(d);
  return Ray(o, d / dist, 0.0f, dist * (1.0f - ShadowEpsilon));
}

}  // namespace femto
