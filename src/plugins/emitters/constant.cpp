// constant: an environment of uniform radiance surrounding the scene, seen by
// every ray that escapes. Sampled uniformly over the sphere of directions.
// Its emitted rays and power cover the scene's bounding sphere (see
// transport/distant_emission.h).
//
// | name            | type  | default | meaning                                      | unit                     |
// |-----------------|-------|---------|----------------------------------------------|--------------------------|
// | radiance        | rgb   | 1       | radiance arriving from every direction       | W / (m^2 sr) per channel |
// | sampling_weight | float | 1       | relative probability of being picked for NEE | -                        |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/transport/distant_emission.h>
#include <femto/render/emitter.h>

namespace femto {

class ConstantEnvironment final : public Emitter {
 public:
  explicit ConstantEnvironment(const Properties& props)
      : Emitter(props), radiance_(props.getColor("radiance", Color3f(1.0f))) {
    if (!radiance_.isValid()) props.raise("radiance", "must be finite and non-negative");
  }

  bool isDelta() const override { return false; }
  bool isEnvironment() const override { return true; }
  void setScene(const Scene& scene) override { sphere_ = SceneSphere::of(scene); }

  Color3f sampleDirection(const Point3f& ref, const Point2f& u, DirectionSample& ds) const override {
    ds = sphere_.directionSample(ref, warp::squareToUniformSphere(u));
    ds.pdf = Inv4Pi;
    return radiance_ * (4.0f * Pi);
  }

  float pdfDirection(const Point3f&, const DirectionSample&) const override { return Inv4Pi; }

  Color3f evalEnvironment(const Ray&) const override { return radiance_; }

  /// Direction uniform on the sphere, origin uniform on the scene's disk
  /// facing it: weight L / (1/(4 pi) * 1/(pi R^2)), the same for every ray.
  Color3f sampleRay(const Point2f& uPosition, const Point2f& uDirection, Ray& ray) const override {
    Vec3f towardEmitter = warp::squareToUniformSphere(uDirection);
    ray = sphere_.rayAlong(-towardEmitter, uPosition);
    return power();
  }

  /// Flux into the scene's bounding sphere: L pi (4 pi R^2).
  Color3f power() const override { return radiance_ * (4.0f * Pi * sphere_.diskArea()); }

  ParameterValues editableParameters() const override { return {{"radiance", parameterValue(radiance_)}}; }
  void setParameter(const std::string& name, const std::vector<double>& value) override {
    if (name != "radiance") return Emitter::setParameter(name, value);
    radiance_ = editableColor(toString(), name, value);
  }

  std::string toString() const override { return str("ConstantEnvironment[radiance=", radiance_, "]"); }

 private:
  Color3f radiance_;
  SceneSphere sphere_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ConstantEnvironment, Emitter, "constant", "Environment of uniform radiance")
