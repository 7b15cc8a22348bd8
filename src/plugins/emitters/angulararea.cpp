// angulararea: mitransient's area light with an angular profile. A shape
// emits radiance from its front side, scaled by a spot light's falloff
// (lights/cone_falloff.h) of the angle between the emitted direction and the
// surface normal: full within beam_width, falling linearly in angle to zero
// at cutoff_angle. With cutoff_angle 90 and beam_width 90 it is `area`.
// Next-event estimation samples the shape uniformly by area (as `area`);
// photons leave uniformly over the shape and uniformly in the cutoff cone.
//
// | name            | type  | default  | meaning                                       | unit                     |
// |-----------------|-------|----------|-----------------------------------------------|--------------------------|
// | radiance        | rgb   | required | emitted radiance along the normal             | W / (m^2 sr) per channel |
// | cutoff_angle    | float | 10       | half-angle beyond which nothing is emitted    | degrees                  |
// | beam_width      | float | cutoff   | half-angle of the fully lit core              | degrees                  |
// | sampling_weight | float | 1        | relative probability of being picked for NEE  | -                        |
// | medium          | medium | none    | accepted as Mitsuba endpoints take it; the shape's interior/exterior decide | - |
#include <femto/core/plugin.h>
#include <femto/math/frame.h>
#include <femto/math/warp.h>
#include <femto/lights/cone_falloff.h>
#include <femto/render/emitter.h>
#include <femto/render/shape.h>
#include <femto/transport/shape_direction_sampling.h>

namespace femto {

class AngularAreaEmitter final : public Emitter {
 public:
  // mitransient's defaults: a 10 degree cone without a soft edge.
  explicit AngularAreaEmitter(const Properties& props)
      : Emitter(props), radiance_(props.getColor("radiance")), falloff_(props, 10.0f, 1.0f) {
    if (!radiance_.isValid()) props.raise("radiance", "must be finite and non-negative");
  }

  void setShape(const Shape* shape) override { shape_ = shape; }
  bool isDelta() const override { return false; }

  Color3f sampleDirection(const Point3f& ref, const Point2f& u, DirectionSample& ds) const override {
    if (!sampleShapeDirection(shape(), ref, u, ds)) return Color3f(0.0f);
    return radiance_ * (falloff_(-dot(ds.n, ds.d)) / ds.pdf);
  }

  float pdfDirection(const Point3f&, const DirectionSample& ds) const override { return shapeDirectionPdf(shape(), ds); }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& w) const override {
    return radiance_ * falloff_(dot(si.n, w));
  }

  /// Uniform point, direction uniform in the cutoff cone around the normal:
  /// weight Le falloff cos / (pdf_pos pdf_dir), whose mean is power().
  Color3f sampleRay(const Point2f& uPosition, const Point2f& uDirection, Ray& ray) const override {
    PositionSample ps = shape().samplePosition(uPosition);
    Vec3f local = warp::squareToUniformCone(uDirection, falloff_.cosCutoff());
    float pdf = warp::squareToUniformConePdf(local, falloff_.cosCutoff());
    SurfaceInteraction si;
    si.p = ps.p;
    si.n = ps.n;
    si.sh = Frame(ps.n);
    ray = si.spawnRay(si.sh.toWorld(local));
    if (!(pdf > 0.0f)) return Color3f(0.0f);
    return radiance_ * (falloff_(local.z) * local.z * shape().surfaceArea() / pdf);
  }

  /// Le A times the falloff's projected solid angle (ConeFalloff::projectedSolidAngle).
  Color3f power() const override { return radiance_ * (shape().surfaceArea() * falloff_.projectedSolidAngle()); }

  std::string toString() const override {
    return str("AngularAreaEmitter[radiance=", radiance_, ", cutoff_angle=", radToDeg(falloff_.cutoff()),
               ", beam_width=", radToDeg(falloff_.beamWidth()), "]");
  }

 private:
  const Shape& shape() const {
    if (!shape_) throw Error("an angulararea emitter must be nested inside a shape");
    return *shape_;
  }

  Color3f radiance_;
  ConeFalloff falloff_;
  const Shape* shape_ = nullptr;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::AngularAreaEmitter, Emitter, "angulararea",
                    "mitransient's area light with a spot-like angular falloff around the normal")
