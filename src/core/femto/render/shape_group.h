#pragma once
// Instancing: a ShapeGroup holds shapes that are never rendered themselves;
// each ShapeInstance places the whole group with its own to_world. The core's
// Embree scene builds a group once (its own Embree scene) and attaches every
// instance as an Embree instance geometry, so memory does not grow with the
// number of instances. Plugins "shapegroup" and "instance" export these.
#include <memory>
#include <vector>

#include <femto/math/transform.h>
#include <femto/render/shape.h>

namespace femto {

class ShapeGroup : public Shape {
 public:
  /// Children: the nested shapes. Refuses nested groups or instances (one
  /// level of instancing, as Embree is built) and area emitters (an emitter
  /// would need one sampling density per instance).
  explicit ShapeGroup(const Properties& props);

  const std::vector<std::shared_ptr<Shape>>& shapes() const { return shapes_; }
  /// Union of the children's bounds, in the group's own space.
  BoundingBox3f bbox() const override { return bbox_; }
  float surfaceArea() const override;
  /// Groups are not sampled (they carry no emitters): throws.
  PositionSample samplePosition(const Point2f& u) const override;
  /// Never hit directly (only through instances): throws.
  void computeInteraction(const Ray& ray, float t, uint32_t primIndex, const Point2f& uv,
                          SurfaceInteraction& si) const override;
  std::string toString() const override;

 private:
  std::vector<std::shared_ptr<Shape>> shapes_;
  BoundingBox3f bbox_;
};

class ShapeInstance : public Shape {
 public:
  /// Reads the referenced shapegroup and `to_world`; refuses a nested emitter.
  explicit ShapeInstance(const Properties& props);

  const ShapeGroup& group() const { return *group_; }
  const Transform& toWorld() const { return toWorld_; }
  const Transform& toLocal() const { return toLocal_; }

  BoundingBox3f bbox() const override { return toWorld_.bbox(group_->bbox()); }
  /// Not defined for instances (a non-uniform scale changes areas unevenly): throws.
  float surfaceArea() const override;
  PositionSample samplePosition(const Point2f& u) const override;
  /// Instances are resolved by the core's Embree scene: throws.
  void computeInteraction(const Ray& ray, float t, uint32_t primIndex, const Point2f& uv,
                          SurfaceInteraction& si) const override;
  /// Map an interaction computed in the group's space to world space
  /// (position, geometric normal, orthonormal shading frame; t is unchanged
  /// because the ray's direction is transformed without normalising it).
  void interactionToWorld(SurfaceInteraction& si) const;
  std::string toString() const override;

 private:
  std::shared_ptr<ShapeGroup> group_;
  Transform toWorld_, toLocal_;
};

}  // namespace femto
