#include <femto/render/volumetric.h>

#include <cmath>

#include <femto/render/bsdf.h>
#include <femto/render/medium.h>
#include <femto/render/scene.h>

namespace femto {
namespace {

/// A connection crossing more boundaries than this is abandoned (guards
/// against rays stuck on coincident or self-intersecting boundaries).
constexpr int kMaxBoundaryCrossings = 256;

}  // namespace

const Medium* mediumAfter(const SurfaceInteraction& si, const Vec3f& d, const Medium* current) {
  const Shape* shape = si.shape;
  if (!shape || (!shape->interiorMedium() && !shape->exteriorMedium())) return current;
  return dot(d, si.n) > 0.0f ? shape->exteriorMedium() : shape->interiorMedium();
}

bool isPassThrough(const SurfaceInteraction& si) {
  const BSDF* bsdf = si.bsdf();
  return !bsdf || bsdf->flags() == BSDFFlags::Null;
}

Connection connect(const Scene& scene, const SurfaceInteraction& from, const Vec3f& d, const Point3f& target,
                   float targetDistance, const Medium* medium, float surfaceEta, Sampler& sampler) {
  Connection result;
  bool finite = std::isfinite(targetDistance);
  Ray ray = finite ? from.spawnRayTo(target) : from.spawnRay(d);
  Point3f start = from.p;
  Color3f tr(1.0f);
  for (int crossing = 0; crossing < kMaxBoundaryCrossings; ++crossing) {
    SurfaceInteraction si;
    bool hit = scene.rayIntersect(ray, si);
    float eta = medium ? medium->eta() : surfaceEta;
    // The shadow ray stops short of the target (ShadowEpsilon); the medium is crossed all the way.
    float segment = hit ? si.t : (finite ? distance(ray.o, target) : Infinity);
    if (medium) tr *= medium->transmittance(ray, segment, sampler);
    if (hit || finite) result.opl += double(eta) * distance(start, hit ? si.p : target);
    if (!hit) {
      result.transmittance = tr;
      return result;
    }
    if (!isPassThrough(si) || tr.isBlack()) return result;
    medium = mediumAfter(si, ray.d, medium);
    start = si.p;
    ray = finite ? si.spawnRayTo(target) : si.spawnRay(ray.d);
  }
  return result;
}

}  // namespace femto
