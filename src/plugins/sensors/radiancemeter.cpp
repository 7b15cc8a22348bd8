// Radiance meter (Mitsuba's `radiancemeter`): measures the radiance arriving
// at one point from one direction. Place it with `origin` and `direction`,
// or with `to_world` (it looks along the transformed +z axis from the
// transformed origin), not both. Without a <film> it gets a 1x1 film; with a
// larger one, every pixel is an independent estimate of the same value.
//
// | name      | type      | default  | meaning                               |
// |-----------|-----------|----------|---------------------------------------|
// | origin    | point     | —        | where the radiance is measured        |
// | direction | vector    | —        | the direction the meter looks in      |
// | to_world  | transform | identity | alternative placement (+z, from 0)    |
#include <femto/core/plugin.h>
#include <femto/render/sensor.h>

namespace femto {

class RadianceMeter final : public Sensor {
 public:
  explicit RadianceMeter(const Properties& props) : Sensor(props) {
    useSinglePixelFilmUnlessGiven(props);
    bool hasOrigin = props.has("origin"), hasDirection = props.has("direction");
    if (hasOrigin != hasDirection)
      props.raise(hasOrigin ? "origin" : "direction", "give both \"origin\" and \"direction\", or \"to_world\"");
    if (hasOrigin) {
      if (props.has("to_world")) props.raise("to_world", "give either \"to_world\" or \"origin\"/\"direction\", not both");
      origin_ = props.getPoint("origin");
      direction_ = props.getVector("direction");
    } else {
      origin_ = toWorld_.point(Point3f(0.0f));
      direction_ = toWorld_.vector(Vec3f(0.0f, 0.0f, 1.0f));
    }
    float len = length(direction_);
    if (!(len > 0.0f)) props.raise(hasDirection ? "direction" : "to_world", "the viewing direction has zero length");
    direction_ = direction_ / len;
  }

  Color3f sampleRay(const Point2f&, const Point2f&, Ray& ray) const override {
    ray = Ray(origin_, direction_);
    return Color3f(1.0f);
  }

  std::string toString() const override {
    return str("RadianceMeter[origin=", origin_, ", direction=", direction_, "]");
  }

 private:
  Point3f origin_;
  Vec3f direction_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::RadianceMeter, Sensor, "radiancemeter", "radiance arriving at a point from one direction")
