#pragma once
// Shapes. Triangle meshes (TriangleMesh) hand their buffers to the core's
// Embree scene; every other shape is an Embree user geometry and implements
// intersect() exactly. Plugins never see Embree.
#include <memory>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/math/bbox.h>
#include <femto/render/interaction.h>

namespace femto {

class BSDF;
class Emitter;
class Medium;
class Sensor;
class TriangleMesh;

/// A point sampled on a surface, with its area-measure density.
struct PositionSample {
  Point3f p;
  Normal3f n;
  Point2f uv;
  float pdf = 0.0f;
};

class Shape : public Object {
 public:
  /// Reads the nested <bsdf> (a shape without one gets Mitsuba's default,
  /// diffuse with reflectance 0.5, unless it only bounds media), an optional
  /// nested area <emitter>, an optional nested <sensor> that measures on the
  /// shape (irradiancemeter) and the media refs "interior"/"exterior".
  explicit Shape(const Properties& props);
  ~Shape() override;
  ObjectKind kind() const override { return ObjectKind::Shape; }

  virtual BoundingBox3f bbox() const = 0;
  virtual float surfaceArea() const = 0;
  /// Uniformly sample a point by area (pdf = 1 / surfaceArea()).
  virtual PositionSample samplePosition(const Point2f& u) const = 0;

  /// Non-null for triangle meshes, which Embree intersects natively.
  virtual const TriangleMesh* asMesh() const { return nullptr; }
  /// Analytic shapes: nearest hit of `ray` in (ray.tmin, ray.tmax), with
  /// shape-specific parameters `uv` passed back to computeInteraction.
  virtual bool intersect(const Ray& ray, float& t, Point2f& uv) const;
  /// Fill `si` (all but t, wi, shape) for a hit found by Embree or intersect().
  virtual void computeInteraction(const Ray& ray, float t, uint32_t primIndex, const Point2f& uv,
                                  SurfaceInteraction& si) const = 0;

  const BSDF* bsdf() const { return bsdf_.get(); }
  const Emitter* emitter() const { return emitter_.get(); }
  const std::shared_ptr<Emitter>& emitterRef() const { return emitter_; }
  /// The sensor nested in this shape, or null.
  const std::shared_ptr<Sensor>& sensorRef() const { return sensor_; }
  const Medium* interiorMedium() const { return interior_.get(); }
  const Medium* exteriorMedium() const { return exterior_.get(); }

 protected:
  std::shared_ptr<BSDF> bsdf_;
  std::shared_ptr<Emitter> emitter_;
  std::shared_ptr<Medium> interior_, exterior_;
  std::shared_ptr<Sensor> sensor_;
};

}  // namespace femto
