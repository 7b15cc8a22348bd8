// spot: a point light shining into a cone, with Mitsuba's falloff: full
// intensity within beam_width of the axis, then falling linearly in angle to
// zero at cutoff_angle. Delta in position: found only by next-event
// estimation. The light sits at to_world(0, 0, 0) and points along
// to_world's +z axis.
//
// An optional texture is projected through the cone like a slide: direction
// (x, y, z) in the light's frame reads uv = 1/2 + (x, y) / (2 z tan(cutoff)).
//
// | name            | type      | default        | meaning                                          | unit        |
// |-----------------|-----------|----------------|--------------------------------------------------|-------------|
// | intensity       | rgb       | 1              | radiant intensity on the axis                    | W / sr per channel |
// | cutoff_angle    | float     | 20             | half-angle of the cone beyond which it is dark   | degrees     |
// | beam_width      | float     | 3/4 cutoff     | half-angle of the fully lit core                 | degrees     |
// | texture         | texture   | none           | modulates the intensity across the cone          | -           |
// | to_world        | transform | identity       | position (origin) and orientation (+z) of the light | -        |
// | sampling_weight | float     | 1              | relative probability of being picked for NEE     | -           |
// | medium          | medium    | none     | the medium the light sits in: a nested <medium> or <ref>, any name (endpoint_medium.h) | - |
#include <femto/core/plugin.h>
#include <femto/math/transform.h>
#include <femto/math/warp.h>
#include <femto/lights/cone_falloff.h>
#include <femto/lights/oriented_point_emitter.h>
#include <femto/render/texture.h>

namespace femto {

class SpotLight final : public OrientedPointEmitter {
 public:
  explicit SpotLight(const Properties& props)
      : OrientedPointEmitter(props),
        intensity_(props.getColor("intensity", Color3f(1.0f))),
        falloff_(props, 20.0f, 0.75f) {
    if (!intensity_.isValid()) props.raise("intensity", "must be finite and non-negative");
    tanCutoff_ = std::tan(falloff_.cutoff());
    if (props.has("texture")) {
      texture_ = std::dynamic_pointer_cast<Texture>(props.getObject("texture"));
      if (!texture_) props.raise("texture", "expected a <texture>");
    }
  }

  /// Uniform directions in the cutoff cone (as Mitsuba): weight I(d) / pdf.
  Color3f sampleRay(const Point2f&, const Point2f& uDirection, Ray& ray) const override {
    Vec3f local = warp::squareToUniformCone(uDirection, falloff_.cosCutoff());
    ray = rayAlongLocal(local);
    float pdf = warp::squareToUniformConePdf(local, falloff_.cosCutoff());
    return pdf > 0.0f ? intensityInLocal(local) / pdf : Color3f(0.0f);
  }

  /// Intensity integrated over the sphere (ConeFalloff::solidAngle). A
  /// texture scales this by its mean (exact for textures uniform over the cone).
  Color3f power() const override {
    Color3f p = intensity_ * falloff_.solidAngle();
    return texture_ ? p * texture_->mean() : p;
  }

  ParameterValues editableParameters() const override { return {{"intensity", parameterValue(intensity_)}}; }
  void setParameter(const std::string& name, const std::vector<double>& value) override {
    if (name != "intensity") return OrientedPointEmitter::setParameter(name, value);
    intensity_ = editableColor(toString(), name, value);
  }

  std::string toString() const override {
    return str("SpotLight[position=", position_, ", intensity=", intensity_, ", cutoff_angle=", radToDeg(falloff_.cutoff()),
               ", beam_width=", radToDeg(falloff_.beamWidth()), texture_ ? str(", texture=", texture_->toString()) : "", "]");
  }

 private:
  /// Mitsuba's falloff for a unit direction in the light's frame.
  Color3f intensityInLocal(const Vec3f& d) const override {
    float falloff = falloff_(d.z);
    if (falloff == 0.0f) return Color3f(0.0f);
    Color3f value = intensity_;
    if (texture_) {
      SurfaceInteraction si;
      si.uv = Point2f(0.5f + 0.5f * d.x / (d.z * tanCutoff_), 0.5f + 0.5f * d.y / (d.z * tanCutoff_));
      value *= texture_->eval(si);
    }
    return falloff == 1.0f ? value : value * falloff;
  }

  Color3f intensity_;
  ConeFalloff falloff_;
  float tanCutoff_;
  std::shared_ptr<Texture> texture_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::SpotLight, Emitter, "spot", "Spot light: a point light with a soft-edged cone")
