// point: an isotropic point light. Delta in position: found only by
// next-event estimation, never by a ray.
//
// | name            | type      | default  | meaning                                   | unit            |
// |-----------------|-----------|----------|-------------------------------------------|-----------------|
// | intensity       | rgb       | 1        | radiant intensity                         | W / sr per channel |
// | position        | point     | (0,0,0)  | where the light is (alternative to to_world) | scene units  |
// | to_world        | transform | identity | places the light at to_world(0, 0, 0)     | -               |
// | sampling_weight | float     | 1        | relative probability of being picked for NEE | -            |
// | medium          | medium    | none     | the medium the light sits in: a nested <medium> or <ref>, any name (endpoint_medium.h) | - |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/emitter.h>

namespace femto {

class PointLight final : public Emitter {
 public:
  explicit PointLight(const Properties& props) : Emitter(props), intensity_(props.getColor("intensity", Color3f(1.0f))) {
    if (!intensity_.isValid()) props.raise("intensity", "must be finite and non-negative");
    if (props.has("position") && props.has("to_world"))
      props.raise("position", "give either \"position\" or \"to_world\", not both");
    position_ = props.has("position") ? props.getPoint("position")
                                      : props.getTransform("to_world", Transform()).point(Point3f(0.0f));
  }

  bool isDelta() const override { return true; }
  bool deltaPosition(Point3f& position) const override {
    position = position_;
    return true;
  }

  Color3f sampleDirection(const Point3f& ref, const Point2f&, DirectionSample& ds) const override {
    float dist2 = sampleDeltaPosition(position_, ref, ds);
    // Inverse-square law: irradiance normal to d is I / r^2.
    return dist2 > 0.0f ? intensity_ / dist2 : Color3f(0.0f);
  }

  float pdfDirection(const Point3f&, const DirectionSample&) const override { return 0.0f; }

  Color3f sampleRay(const Point2f&, const Point2f& uDirection, Ray& ray) const override {
    ray = Ray(position_, warp::squareToUniformSphere(uDirection));
    return power();  // I / (1 / 4pi)
  }

  Color3f power() const override { return intensity_ * (4.0f * Pi); }
  ParameterValues editableParameters() const override { return {{"intensity", parameterValue(intensity_)}}; }
  void setParameter(const std::string& name, const std::vector<double>& value) override {
    if (name != "intensity") return Emitter::setParameter(name, value);
    intensity_ = editableColor(toString(), name, value);
  }

  std::string toString() const override { return str("PointLight[position=", position_, ", intensity=", intensity_, "]"); }

 private:
  Color3f intensity_;
  Point3f position_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::PointLight, Emitter, "point", "Isotropic point light")
