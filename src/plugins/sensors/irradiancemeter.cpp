// Irradiance meter (Mitsuba's `irradiancemeter`): nested in a <shape>, it
// measures the irradiance averaged over the shape's surface, on the side its
// normals point to:  E = (1/A) \int_A \int_{H^2} L(x, w) cos(theta) dw dx.
// Each sample picks a point uniformly by area (density 1/A, which cancels
// the 1/A) and a cosine-distributed direction (density cos(theta)/pi), so
// the ray weight is pi. The area sample comes from the position inside the
// pixel, the direction from the aperture sample. Without a <film> it gets a
// 1x1 film; with a larger one every pixel estimates the same value.
// No parameters (the shape places it; a `to_world` is refused as in Mitsuba).
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/sensor.h>
#include <femto/render/shape.h>

namespace femto {

class IrradianceMeter final : public Sensor {
 public:
  explicit IrradianceMeter(const Properties& props) : Sensor(props) {
    if (props.has("to_world"))
      props.raise("to_world", "an irradiance meter takes its placement from the shape it is nested in");
    useSinglePixelFilmUnlessGiven(props);
  }

  void setShape(const Shape* shape) override { shape_ = shape; }
  bool requiresShape() const override { return true; }

  Color3f sampleRay(const Point2f& filmPos, const Point2f& u, Ray& ray) const override {
    Point2f uArea(filmPos.x - std::floor(filmPos.x), filmPos.y - std::floor(filmPos.y));
    PositionSample ps = shape_->samplePosition(uArea);
    SurfaceInteraction si;
    si.p = ps.p;
    si.n = ps.n;
    Vec3f d = Frame(ps.n).toWorld(warp::squareToCosineHemisphere(u));
    ray = si.spawnRay(d);
    return Color3f(Pi);
  }

  std::string toString() const override { return "IrradianceMeter[]"; }

 private:
  const Shape* shape_ = nullptr;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::IrradianceMeter, Sensor, "irradiancemeter", "irradiance averaged over the shape it is nested in")
