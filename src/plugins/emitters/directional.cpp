// directional: light from infinitely far away arriving along one direction
// (the sun), delivering `irradiance` to a surface facing it. Delta in
// direction: found only by next-event estimation. Its emitted rays and power
// cover the scene's bounding sphere (see transport/distant_emission.h).
//
// | name            | type      | default  | meaning                                              | unit      |
// |-----------------|-----------|----------|------------------------------------------------------|-----------|
// | irradiance      | rgb       | 1        | irradiance on a surface perpendicular to the light   | W / m^2 per channel |
// | direction       | vector    | -        | direction the light travels (alternative to to_world) | -        |
// | to_world        | transform | identity | the light travels along to_world's +z axis           | -         |
// | sampling_weight | float     | 1        | relative probability of being picked for NEE         | -         |
#include <femto/core/plugin.h>
#include <femto/math/transform.h>
#include <femto/transport/distant_emission.h>
#include <femto/render/emitter.h>

namespace femto {

class DirectionalLight final : public Emitter {
 public:
  explicit DirectionalLight(const Properties& props)
      : Emitter(props), irradiance_(props.getColor("irradiance", Color3f(1.0f))) {
    if (!irradiance_.isValid()) props.raise("irradiance", "must be finite and non-negative");
    if (props.has("direction") && props.has("to_world"))
      props.raise("direction", "give either \"direction\" or \"to_world\", not both");
    const char* source = props.has("direction") ? "direction" : "to_world";
    Vec3f d = props.has("direction") ? props.getVector("direction")
                                     : props.getTransform("to_world", Transform()).vector(Vec3f(0, 0, 1));
    if (!(squaredLength(d) > 0.0f) || !isFinite(d)) props.raise(source, "does not give a direction (zero length)");
    direction_ = normalize(d);
  }

  bool isDelta() const override { return true; }
  void setScene(const Scene& scene) override { sphere_ = SceneSphere::of(scene); }

  Color3f sampleDirection(const Point3f& ref, const Point2f&, DirectionSample& ds) const override {
    ds = sphere_.directionSample(ref, -direction_);
    ds.pdf = 1.0f;
    ds.delta = true;
    return irradiance_;
  }

  float pdfDirection(const Point3f&, const DirectionSample&) const override { return 0.0f; }

  /// A parallel beam over the scene's disk: weight E / (1 / (pi R^2)).
  Color3f sampleRay(const Point2f& uPosition, const Point2f&, Ray& ray) const override {
    ray = sphere_.rayAlong(direction_, uPosition);
    return power();
  }

  Color3f power() const override { return irradiance_ * sphere_.diskArea(); }

  std::string toString() const override {
    return str("DirectionalLight[direction=", direction_, ", irradiance=", irradiance_, "]");
  }

 private:
  Color3f irradiance_;
  Vec3f direction_;
  SceneSphere sphere_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::DirectionalLight, Emitter, "directional", "Distant light from one direction (sun)")
