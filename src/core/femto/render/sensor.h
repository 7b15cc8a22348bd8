#pragma once
// Cameras. A sensor owns its film and sampler (nested in the XML).
#include <memory>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/math/transform.h>
#include <femto/render/film.h>
#include <femto/render/sampler.h>

namespace femto {

class Medium;
class Shape;

class Sensor : public Object {
 public:
  /// Reads "to_world", the nested <film> (default hdrfilm) and <sampler>
  /// (default independent), the medium the camera sits in (endpoint_medium.h), and
  /// Mitsuba's "shutter_open"/"shutter_close" (accepted; scenes are static).
  explicit Sensor(const Properties& props);
  ObjectKind kind() const override { return ObjectKind::Sensor; }

  /// Primary ray through continuous film position `filmPos` (in pixels of the
  /// full film) with aperture sample `u`; returns the importance weight.
  virtual Color3f sampleRay(const Point2f& filmPos, const Point2f& u, Ray& ray) const = 0;

  /// Sensors nested in a <shape> (Mitsuba's irradiancemeter) are attached to
  /// it by the Shape constructor; the default refuses, naming the sensor.
  /// As with emitters, the shape's geometry is not built yet: only remember it.
  virtual void setShape(const Shape* shape);
  /// True for sensors that only make sense nested in a shape (the scene
  /// refuses them at top level).
  virtual bool requiresShape() const { return false; }

  const Film& film() const { return *film_; }
  /// For the scene's set-up only (an integrator's settings for the film).
  Film& film() { return *film_; }
  const Sampler& sampler() const { return *sampler_; }
  const Transform& toWorld() const { return toWorld_; }
  const Medium* medium() const { return medium_.get(); }

 protected:
  /// For meters, which measure one value: when the scene gave no <film>,
  /// replace the default 768x576 film by a 1x1 hdrfilm with a box filter.
  void useSinglePixelFilmUnlessGiven(const Properties& props);

  Transform toWorld_;
  std::shared_ptr<Film> film_;
  std::shared_ptr<Sampler> sampler_;
  std::shared_ptr<Medium> medium_;
};

}  // namespace femto
