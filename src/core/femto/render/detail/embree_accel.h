#pragma once
// INTERNAL to the femto core: not part of the plugin API. The Embree
// acceleration structure behind Scene::rayIntersect/rayTest. Embree's own
// headers are only included by embree_accel.cpp, so nothing installed
// depends on them (plugins never see Embree).
#include <memory>
#include <vector>

#include <femto/math/ray.h>
#include <femto/render/interaction.h>

namespace femto {
class Shape;
}

namespace femto::detail {

class EmbreeAccel {
 public:
  /// Triangle meshes become Embree triangle geometry (buffers copied); every
  /// other shape a user geometry calling Shape::intersect. A ShapeGroup
  /// becomes its own Embree scene (built once, when first instanced) and each
  /// ShapeInstance an Embree instance of it. `shapes` must outlive this.
  explicit EmbreeAccel(const std::vector<std::shared_ptr<Shape>>& shapes);
  ~EmbreeAccel();
  EmbreeAccel(const EmbreeAccel&) = delete;
  EmbreeAccel& operator=(const EmbreeAccel&) = delete;

  /// Nearest hit in (ray.tmin, ray.tmax); fills t, shape, primIndex and
  /// everything computeInteraction provides, plus wi.
  bool intersect(const Ray& ray, SurfaceInteraction& si) const;
  /// Nearest hit in (ray.tmin, ray.tmax) without its interaction.
  bool intersectPreliminary(const Ray& ray, PreliminaryHit& hit) const;
  /// The interaction of `hit`, found for the same `ray`: what intersect fills.
  void computeInteraction(const Ray& ray, const PreliminaryHit& hit, SurfaceInteraction& si) const;
  /// Nearest hit distance, Infinity when none (no interaction computed).
  float hitDistance(const Ray& ray) const;
  bool occluded(const Ray& ray) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace femto::detail
