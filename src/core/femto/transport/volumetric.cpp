#include <femto/transport/volumetric.h>

#include <cmath>

#include <femto/core/log.h>
#include <femto/render/bsdf.h>
#include <femto/render/medium.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/render/shape_group.h>

namespace femto {
const Medium* mediumAfter(const SurfaceInteraction& si, const Vec3f& d, const Medium* current) {
  const Shape* shape = si.shape;
  if (!shape || (!shape->interiorMedium() && !shape->exteriorMedium())) return current;
  return dot(d, si.n) > 0.0f ? shape->exteriorMedium() : shape->interiorMedium();
}

bool isPassThrough(const SurfaceInteraction& si) { return isPassThrough(si.bsdf()); }

Connection connect(const Scene& scene, const SurfaceInteraction& from, const Vec3f& d, const Point3f& target,
                   float targetDistance, const Medium* medium, float surfaceEta, Sampler& sampler) {
  Connection result;
  bool finite = std::isfinite(targetDistance);
  Ray ray = finite ? from.spawnRayTo(target) : from.spawnRay(d);
  // Nothing to cross and no medium to attenuate: an occlusion test decides,
  // cheaper than the full intersection the loop below needs (surface-only
  // scenes then cost transient_path what they cost `path`).
  if (!medium && !scene.hasPassThroughShapes()) {
    if (scene.rayTest(ray)) return result;
    if (finite) result.opl = double(surfaceEta) * distance(from.p, target);
    result.transmittance = Color3f(1.0f);
    return result;
  }
  Point3f start = from.p;
  Color3f tr(1.0f);
  for (int crossing = 0; crossing < MaxPassThrough; ++crossing) {
    PreliminaryHit ahead;
    bool hit = scene.rayIntersectPreliminary(ray, ahead);
    float eta = medium ? medium->eta() : surfaceEta;
    // The shadow ray stops short of the target (ShadowEpsilon); the medium is crossed all the way.
    float segment = hit ? ahead.t : (finite ? distance(ray.o, target) : Infinity);
    if (medium) tr *= medium->transmittance(ray, segment, sampler);
    if (!hit) {
      if (finite) result.opl += double(eta) * distance(start, target);
      result.transmittance = tr;
      return result;
    }
    // Occluded: the surface's interaction is not needed (PreliminaryHit).
    if (!isPassThrough(ahead.shape->bsdf()) || tr.isBlack()) return result;
    SurfaceInteraction si;
    scene.computeInteraction(ray, ahead, si);
    result.opl += double(eta) * distance(start, si.p);
    medium = mediumAfter(si, ray.d, medium);
    start = si.p;
    ray = finite ? si.spawnRayTo(target) : si.spawnRay(ray.d);
  }
  return result;
}

bool sceneHasMedia(const Scene& scene) {
  auto bounds = [](const Shape& shape) { return shape.interiorMedium() || shape.exteriorMedium(); };
  for (const auto& shape : scene.shapes()) {
    if (bounds(*shape)) return true;
    if (auto group = dynamic_cast<const ShapeGroup*>(shape.get()))
      for (const auto& child : group->shapes())
        if (bounds(*child)) return true;
  }
  return scene.sensor().medium() != nullptr;
}

void warnIfMediaIgnored(const Scene& scene, const char* integrator) {
  if (sceneHasMedia(scene))
    logWarn(integrator, ": the scene has participating media, which this integrator ignores (surfaces only); "
                        "render media with transient_path (Mitsuba's volpath loads as it) or transient_beams");
}

}  // namespace femto
