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

namespace femto {

class AreaEmitter final : public Emitter {
 public:
  explicit AreaEmitter(const Properties& props) : Emitter(props), radiance_(props.getColor("radiance")) {
    if (!radiance_.isValid()) props.raise("radiance", "must be finite and non-negative");
  }

  void setShape(const Shape* shape) override { shape_ = shape; }
  bool isDelta() const override { return false; }

  Color3f sampleDirection(const Point3f& ref, const Point2f& u, DirectionSample& ds) const override {
    ds = DirectionSample();
    PositionSample ps = shape().samplePosition(u);
    Vec3f toLight = ps.p - ref;
    float dist2 = squaredLength(toLight);
    if (!(dist2 > 0.0f)) return Color3f(0.0f);
    ds.p = ps.p;
    ds.n = ps.n;
    ds.dist = std::sqrt(dist2);
    ds.d = toLight / ds.dist;
    ds.pdf = pdfDirection(ref, ds);
    if (!(ds.pdf > 0.0f) || !std::isfinite(ds.pdf)) {
      ds.pdf = 0.0f;
      return Color3f(0.0f);
    }
    return radiance_ / ds.pdf;
  }

  /// Area density 1/A times the Jacobian dist^2 / cos(theta_light) of the
  /// area-to-solid-angle change of measure (Veach 1997, eq. 8.10); zero when
  /// the reference point sees the back of the emitter, which emits nothing.
  float pdfDirection(const Point3f&, const DirectionSample& ds) const override {
    float cosLight = -dot(ds.n, ds.d);
    if (cosLight <= 0.0f) return 0.0f;
    return ds.dist * ds.dist / (cosLight * shape().surfaceArea());
  }

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
