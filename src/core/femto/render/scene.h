#pragma once
// The scene: shapes in an Embree BVH (kept inside the core), emitters, the
// sensor and the integrator. Created by the loader from the <scene> element.
#include <memory>
#include <vector>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/math/bbox.h>
#include <femto/render/emitter.h>
#include <femto/render/integrator.h>
#include <femto/render/interaction.h>
#include <femto/render/sensor.h>
#include <femto/render/shape.h>

namespace femto {

class Scene : public Object {
 public:
  /// Children: shapes, emitters, one sensor (default perspective), one
  /// integrator (default path). Builds the acceleration structure.
  explicit Scene(const Properties& props);
  ~Scene() override;
  ObjectKind kind() const override { return ObjectKind::Scene; }

  /// Nearest surface hit in (ray.tmin, ray.tmax); fills `si` (including wi and shape).
  bool rayIntersect(const Ray& ray, SurfaceInteraction& si) const;
  /// The same hit without its interaction (PreliminaryHit), and the
  /// interaction later, for the same ray: rayIntersect in two steps.
  bool rayIntersectPreliminary(const Ray& ray, PreliminaryHit& hit) const;
  void computeInteraction(const Ray& ray, const PreliminaryHit& hit, SurfaceInteraction& si) const;
  /// Distance to the nearest hit in (ray.tmin, ray.tmax), Infinity when none;
  /// computes no interaction (for callers that only need t, and benchmarks).
  float rayHitDistance(const Ray& ray) const;
  /// Is anything hit in (ray.tmin, ray.tmax)? (shadow rays)
  bool rayTest(const Ray& ray) const;

  /// Pick an emitter proportionally to its sampling weight and sample a
  /// direction toward it from `ref`; returns radiance / (pick * direction pdf),
  /// zero when occluded (if `testVisibility`). ds.pdf includes the pick probability.
  Color3f sampleEmitterDirection(const SurfaceInteraction& ref, const Point2f& u, DirectionSample& ds,
                                 bool testVisibility = true) const;
  /// Density (pick probability times solid angle) of sampleEmitterDirection
  /// choosing point ds.p of `emitter` from `ref`.
  float pdfEmitterDirection(const Point3f& ref, const DirectionSample& ds, const Emitter* emitter) const;
  /// The emitter sampleEmitterDirection picks with u.x = `u` (nullptr when no
  /// emitter has weight); `u` becomes the part of it inside the emitter's
  /// interval, rescaled to [0, 1) for reuse.
  const Emitter* pickEmitter(float& u) const;
  /// Probability that sampleEmitterDirection picks `emitter`.
  float emitterPickProbability(const Emitter* emitter) const;

  const std::vector<std::shared_ptr<Shape>>& shapes() const { return shapes_; }
  const std::vector<std::shared_ptr<Emitter>>& emitters() const { return emitters_; }
  /// Environment emitters, looked up when a ray escapes.
  const std::vector<const Emitter*>& environmentEmitters() const { return environment_; }
  Color3f evalEnvironment(const Ray& ray) const;

  const Sensor& sensor() const { return *sensor_; }
  const Integrator& integrator() const { return *integrator_; }
  const BoundingBox3f& bbox() const { return bbox_; }
  /// Does any shape (or shape of a group) let paths cross it unchanged
  /// (isPassThrough in volumetric.h: media boundaries)? When none does, a
  /// connection outside media is a plain shadow ray.
  bool hasPassThroughShapes() const { return hasPassThroughShapes_; }
  /// Does any shape (or shape of a group) have a BSDF with a smooth
  /// (non-delta) lobe? When none does, light never scatters diffusely off a
  /// surface: a surface photon map would stay empty.
  bool hasSmoothSurfaces() const { return hasSmoothSurfaces_; }
  /// The largest refractive index of the media the scene names (shapes'
  /// interiors and exteriors, shapegroups' shapes included, the sensor's and
  /// the emitters'), at least 1: light crossing a length d through them takes
  /// at most this times d of OPL (time gating's bounds).
  float largestMediumEta() const { return largestMediumEta_; }

 private:
  void warnIfEmpty(const Properties& props) const;
  struct Accel;  // Embree state (detail/embree_accel.h, internal to the core)
  std::unique_ptr<Accel> accel_;
  std::vector<std::shared_ptr<Shape>> shapes_;
  std::vector<std::shared_ptr<Emitter>> emitters_;
  std::vector<const Emitter*> environment_;
  std::vector<float> emitterCdf_;
  float emitterWeightSum_ = 0.0f;
  std::shared_ptr<Sensor> sensor_;
  std::shared_ptr<Integrator> integrator_;
  BoundingBox3f bbox_;
  bool hasPassThroughShapes_ = false;
  bool hasSmoothSurfaces_ = false;
  float largestMediumEta_ = 1.0f;
};

}  // namespace femto
