#pragma once
// Light sources. Directions are world space. Area emitters are attached to a
// shape (setShape) by the Shape constructor.
#include <cmath>
#include <memory>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/time/emission_pulse.h>
#include <femto/render/interaction.h>
#include <femto/math/spectrum.h>

namespace femto {

class Emitter;
class Medium;
class Shape;
class Scene;

/// A point on an emitter chosen for next-event estimation from a reference point.
struct DirectionSample {
  Point3f p;          // point on the emitter
  Normal3f n;         // its normal (zero for point lights)
  Vec3f d;            // unit direction from the reference point to p
  float dist = 0.0f;  // distance from the reference point to p (Infinity for distant lights)
  float pdf = 0.0f;   // solid-angle density at the reference point (1 for delta lights)
  bool delta = false;
  const Emitter* emitter = nullptr;  // set by Scene::sampleEmitterDirection (its pulse, for transient integrators)
};

/// Next-event sample of a light at a single `position` (point and spot
/// lights): fills `ds` as a delta sample seen from `ref` and returns the
/// squared distance for the inverse-square law, or 0 (ds left empty) when
/// `ref` sits on the light.
inline float sampleDeltaPosition(const Point3f& position, const Point3f& ref, DirectionSample& ds) {
  ds = DirectionSample();
  Vec3f toLight = position - ref;
  float dist2 = squaredLength(toLight);
  if (!(dist2 > 0.0f)) return 0.0f;
  ds.p = position;
  ds.dist = std::sqrt(dist2);
  ds.d = toLight / ds.dist;
  ds.pdf = 1.0f;
  ds.delta = true;
  return dist2;
}

class Emitter : public Object {
 public:
  /// Reads "sampling_weight" (default 1) and the temporal profile (`pulse`,
  /// `pulse_sigma`/`pulse_fwhm`, `pulse_width`, `pulse_offset`: emission_pulse.h)
  /// and the medium the emitter sits in (endpoint_medium.h).
  explicit Emitter(const Properties& props);
  ObjectKind kind() const override { return ObjectKind::Emitter; }

  /// Sample a point on the emitter seen from `ref`. Returns the incident
  /// radiance divided by pdf (for delta lights, intensity / dist^2), ignoring
  /// visibility; black when nothing can be sampled.
  virtual Color3f sampleDirection(const Point3f& ref, const Point2f& u, DirectionSample& ds) const = 0;
  /// Solid-angle density of sampleDirection choosing ds.p from `ref`.
  virtual float pdfDirection(const Point3f& ref, const DirectionSample& ds) const = 0;
  /// Radiance leaving point `si` of this emitter's shape toward world direction `w`.
  virtual Color3f eval(const SurfaceInteraction& si, const Vec3f& w) const;
  /// Radiance arriving along a ray that escapes the scene (environment emitters).
  virtual Color3f evalEnvironment(const Ray& ray) const;
  /// Sample an emitted ray (photon tracing): returns power / (pdf_pos * pdf_dir).
  virtual Color3f sampleRay(const Point2f& uPosition, const Point2f& uDirection, Ray& ray) const;
  /// Total emitted power (watts in scene units), used to pick emitters for photons.
  virtual Color3f power() const;

  virtual bool isDelta() const = 0;
  /// Lights at a single point (point, spot, projector): that point. Volumetric
  /// integrators sample distances along rays toward it (transport/equiangular.h).
  virtual bool deltaPosition(Point3f& /*position*/) const { return false; }
  virtual bool isEnvironment() const { return false; }
  /// Area emitters only: the shape they sit on.
  virtual void setShape(const Shape* shape);
  /// Called once the scene exists (environment emitters need its bounds).
  virtual void setScene(const Scene& scene);

  float samplingWeight() const { return samplingWeight_; }
  /// When this emitter emits (transient rendering); a Dirac at OPL 0 by default.
  const EmissionPulse& pulse() const { return pulse_; }
  /// The medium the scene says the emitter sits in, or null (then light
  /// tracers find it from the geometry around the emitter). Camera-side
  /// integrators need no such hint: next-event estimation connects from the
  /// medium of the path vertex and tracks the boundaries it crosses.
  const Medium* medium() const { return medium_.get(); }

 private:
  float samplingWeight_ = 1.0f;
  EmissionPulse pulse_;
  std::shared_ptr<Medium> medium_;
};

}  // namespace femto
