#pragma once
// A point light whose intensity depends on direction (spot, projector): it
// sits at to_world(0, 0, 0), looks along to_world's +z axis, and is found only
// by next-event estimation (delta in position). Derived lights say how bright
// they are toward each direction of their own frame.
#include <femto/math/transform.h>
#include <femto/render/emitter.h>

namespace femto {

class OrientedPointEmitter : public Emitter {
 public:
  /// Reads "to_world" (identity by default) besides what Emitter reads.
  explicit OrientedPointEmitter(const Properties& props)
      : Emitter(props), toWorld_(props.getTransform("to_world", Transform())), position_(toWorld_.point(Point3f(0.0f))) {}

  bool isDelta() const override { return true; }
  bool deltaPosition(Point3f& position) const override {
    position = position_;
    return true;
  }

  Color3f sampleDirection(const Point3f& ref, const Point2f&, DirectionSample& ds) const override {
    float dist2 = sampleDeltaPosition(position_, ref, ds);
    if (!(dist2 > 0.0f)) return Color3f(0.0f);
    // Intensity toward the reference point, over distance squared (inverse-square law).
    return intensityInLocal(normalize(toWorld_.inverse().vector(-ds.d))) / dist2;
  }

  float pdfDirection(const Point3f&, const DirectionSample&) const override { return 0.0f; }

  /// Where the light sits and how it is turned (NLOS integrators aim a laser
  /// from its own frame: transient_nlos_path).
  const Transform& toWorld() const { return toWorld_; }

 protected:
  /// Radiant intensity toward unit direction `d` of the light's frame (+z forward).
  virtual Color3f intensityInLocal(const Vec3f& d) const = 0;
  /// The emitted ray along a direction of the light's frame (need not be unit).
  Ray rayAlongLocal(const Vec3f& local) const { return Ray(position_, normalize(toWorld_.vector(local))); }

  Transform toWorld_;
  Point3f position_;
};

}  // namespace femto
