// area: a shape that emits constant radiance from its front side (the side its
// normal points to). Next-event estimation samples the shape uniformly by
// area and converts that density to solid angle at the receiving point.
//
// | name            | type  | default  | meaning                                   | unit                   |
// |-----------------|-------|----------|-------------------------------------------|------------------------|
// | radiance        | rgb   | required | emitted radiance                          | W / (m^2 sr) per channel |
// | sampling_weight | float | 1        | relative probability of being picked for NEE | -                   |
// | medium          | medium | none    | accepted as Mitsuba endpoints take it; the shape's interior/exterior decide | - |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/emitter.h>
#include <femto/render/shape.h>
#include <femto/transport/shape_direction_sampling.h>

namespace femto {

class AreaEmitter final : public Emitter {
 public:
  explicit AreaEmitter(const Properties& props) : Emitter(props), radiance_(props.getColor("radiance")) {
    if (!radiance_.isValid()) props.raise("radiance", "must be finite and non-negative");
  }

  void setShape(const Shape* shape) override { shape_ = shape; }
  bool isDelta() const override { return false; }

  Color3f sampleDirection(const Point3f& ref, const Point2f& u, DirectionSample& ds) const override {
    if (!sampleShapeDirection(shape(), ref, u, ds)) return Color3f(0.0f);
    return radiance_ / ds.pdf;
  }

  float pdfDirection(const Point3f&, const DirectionSample& ds) const override { return shapeDirectionPdf(shape(), ds); }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& w) const override {
    return dot(si.n, w) > 0.0f ? radiance_ : Color3f(0.0f);
  }

  /// Uniform point, cosine-weighted direction: the weight
  /// Le cos / (pdf_pos pdf_dir) = Le pi A is the same for every ray.
  Color3f sampleRay(const Point2f& uPosition, const Point2f& uDirection, Ray& ray) const override {
    PositionSample ps = shape().samplePosition(uPosition);
    SurfaceInteraction si;
    si.p = ps.p;
    si.n = ps.n;
    si.sh = Frame(ps.n);
    ray = si.spawnRay(si.sh.toWorld(warp::squareToCosineHemisphere(uDirection)));
    return power();
  }

  Color3f power() const override { return radiance_ * (Pi * shape().surfaceArea()); }
  ParameterValues editableParameters() const override { return {{"radiance", parameterValue(radiance_)}}; }
  void setParameter(const std::string& name, const std::vector<double>& value) override {
    if (name != "radiance") return Emitter::setParameter(name, value);
    radiance_ = editableColor(toString(), name, value);
  }

  std::string toString() const override { return str("AreaEmitter[radiance=", radiance_, "]"); }

 private:
  const Shape& shape() const {
    if (!shape_) throw Error("an area emitter must be nested inside a shape");
    return *shape_;
  }

  Color3f radiance_;
  const Shape* shape_ = nullptr;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::AreaEmitter, Emitter, "area", "Diffuse area light on a shape")
