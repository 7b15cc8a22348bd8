// projector: a point light that projects an image like a slide projector (the
// reverse of a perspective camera, as Mitsuba 3's projector). The image is
// the irradiance it casts on a virtual image plane at distance 1 in front of
// the light: the plane spans [-tan(fov/2), tan(fov/2)] along the light's x
// axis and the same times height/width (the texture's aspect ratio) along y,
// with the image's top-left corner at local (+x, +y), as femto's perspective
// camera sees its film from the same to_world. Delta in position: found only
// by next-event estimation.
//
// Irradiance E on the plane at unit distance from a point source of
// intensity I is E = I cos^3(theta) (inverse square of 1/cos(theta), times
// the cosine of incidence), so the intensity toward a direction with
// cos(theta) = z is I = scale * E(uv) / z^3 and the power is exactly
// scale * mean(E) * (area of the plane): photons are emitted uniformly over
// the plane, each carrying power / (number of photons) in expectation.
//
// | name       | type      | default  | meaning                                                   | unit   |
// |------------|-----------|----------|-----------------------------------------------------------|--------|
// | irradiance | texture   | 1        | irradiance on the image plane at distance 1 (bitmap or rgb) | W / m^2 per channel |
// | scale      | float     | 1        | multiplies the irradiance                                 | -      |
// | fov        | float     | 28.8415  | horizontal field of view (Mitsuba 3's default: 50 mm lens)  | degrees |
// | to_world   | transform | identity | position (origin) and orientation (+z forward, +y up)     | -      |
// | sampling_weight | float | 1       | relative probability of being picked for NEE              | -      |
// | medium          | medium    | none     | the medium the light sits in: a nested <medium> or <ref>, any name (endpoint_medium.h) | - |
#include <cmath>
#include <limits>

#include <femto/core/plugin.h>
#include <femto/math/transform.h>
#include <femto/lights/oriented_point_emitter.h>
#include <femto/render/texture.h>

namespace femto {

class ProjectorLight final : public OrientedPointEmitter {
 public:
  explicit ProjectorLight(const Properties& props)
      : OrientedPointEmitter(props),
        irradiance_(textureOrColor(props, "irradiance", Color3f(1.0f))),
        scale_(props.getFloat("scale", 1.0f, Range::nonNegative())) {
    fov_ = props.getFloat("fov", 28.8415f, Range::open(0, 180), "degrees");
    Point2i size = irradiance_->resolution();
    float aspect = size.x > 0 && size.y > 0 ? float(size.y) / float(size.x) : 1.0f;
    tanX_ = std::tan(degToRad(fov_) * 0.5f);
    tanY_ = tanX_ * aspect;
  }

  /// Uniform over the image plane: the direction density is
  /// 1 / (planeArea z^3) (d omega = z^3 dA at unit distance), so the weight I / pdf is scale * E(uv) * planeArea.
  Color3f sampleRay(const Point2f&, const Point2f& uDirection, Ray& ray) const override {
    Vec3f local((1.0f - 2.0f * uDirection.x) * tanX_, (1.0f - 2.0f * uDirection.y) * tanY_, 1.0f);
    ray = rayAlongLocal(local);
    return irradianceAt(uDirection) * (scale_ * planeArea());
  }

  Color3f power() const override { return irradiance_->mean() * (scale_ * planeArea()); }

  /// The projector's brightness (its irradiance image is fixed at load).
  ParameterValues editableParameters() const override { return {{"scale", {double(scale_)}}}; }
  void setParameter(const std::string& name, const std::vector<double>& value) override {
    if (name != "scale") return OrientedPointEmitter::setParameter(name, value);
    scale_ = float(editableNumber(toString(), name, value, 0.0, std::numeric_limits<float>::max()));
  }

  std::string toString() const override {
    return str("ProjectorLight[position=", position_, ", fov=", fov_, ", scale=", scale_,
               ", irradiance=", irradiance_->toString(), "]");
  }

 private:
  float planeArea() const { return 4.0f * tanX_ * tanY_; }

  Color3f irradianceAt(const Point2f& uv) const {
    SurfaceInteraction si;
    si.uv = uv;
    return irradiance_->eval(si);
  }

  /// scale * E(uv) / z^3 for a unit direction in the light's frame; black
  /// outside the image's frustum.
  Color3f intensityInLocal(const Vec3f& d) const override {
    if (!(d.z > 0.0f)) return Color3f(0.0f);
    Point2f uv(0.5f * (1.0f - d.x / (d.z * tanX_)), 0.5f * (1.0f - d.y / (d.z * tanY_)));
    if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) return Color3f(0.0f);
    return irradianceAt(uv) * (scale_ / (d.z * d.z * d.z));
  }

  std::shared_ptr<Texture> irradiance_;
  float scale_;
  float fov_ = 0.0f, tanX_ = 0.0f, tanY_ = 0.0f;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ProjectorLight, Emitter, "projector",
                    "Projector: a point light casting an image (irradiance on a plane at distance 1)")
