#pragma once
// The laser of a non-line-of-sight capture, aimed at a wall point. mitransient
// points its projector with look_at(laser_origin, target, up = +y); here the
// emitter keeps its own to_world and is queried in a turned frame instead:
// a point seen from the aimed laser is the point that, turned about the
// laser by the rotation from the aimed frame to the emitter's own, the
// emitter sees. Its intensity, inverse-square law and emitted rays are then
// exactly those of the same projector placed with the look-at transform, and
// one emitter serves every target of a confocal scan.
#include <femto/math/frame.h>
#include <femto/math/ray.h>
#include <femto/render/emitter.h>

namespace femto {

class AimedLaser {
 public:
  /// `emitter` at `origin` (its own position when none is given), aimed at
  /// `target`. Lights that are not oriented (a point light) are only moved.
  AimedLaser(const Emitter& emitter, const std::optional<Point3f>& origin, const Point3f& target);
  /// `emitter` as the scene places it (an ordinary camera's NLOS scene).
  explicit AimedLaser(const Emitter& emitter);

  const Emitter& emitter() const { return *emitter_; }
  const Point3f& origin() const { return origin_; }

  /// Intensity toward `ref` over its squared distance (ignoring visibility);
  /// ds.d is the unit direction from `ref` to the laser, ds.dist the distance.
  Color3f incident(const Point3f& ref, DirectionSample& ds) const;
  /// An emitted ray from the laser (uDirection picks its direction) and its
  /// weight: intensity / solid-angle density.
  Color3f sampleRay(const Point2f& uPosition, const Point2f& uDirection, Ray& ray) const;

 private:
  const Emitter* emitter_;
  Point3f origin_;    // where the aimed laser sits
  Point3f position_;  // where the emitter itself sits
  Frame aimed_;       // look-at frame toward the target (+z forward, +y up)
  Frame own_;         // the emitter's own frame
};

}  // namespace femto
