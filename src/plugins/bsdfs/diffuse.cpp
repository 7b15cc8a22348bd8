// diffuse: the ideal Lambertian reflector, f = reflectance / pi. One-sided,
// as in Mitsuba: light arriving or leaving below the shading surface is
// absorbed. Importance sampled with the cosine-weighted hemisphere, so a
// sample's weight f cos / pdf is exactly the reflectance.
//
// | name        | type            | default | meaning                                 | unit |
// |-------------|-----------------|---------|-----------------------------------------|------|
// | reflectance | rgb or texture  | 0.5     | diffuse albedo (fraction reflected)     | -    |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/bsdf.h>
#include <femto/render/texture.h>

namespace femto {

class DiffuseBSDF final : public BSDF {
 public:
  explicit DiffuseBSDF(const Properties& props) : reflectance_(textureOrColor(props, "reflectance", Color3f(0.5f))) {}

  uint32_t flags() const override { return BSDFFlags::DiffuseReflection; }

  Color3f sample(const SurfaceInteraction& si, float, const Point2f& u2, BSDFSample& bs,
                 TransportMode) const override {
    bs = BSDFSample();
    if (Frame::cosTheta(si.wi) <= 0.0f) return Color3f(0.0f);
    bs.wo = warp::squareToCosineHemisphere(u2);
    bs.pdf = warp::squareToCosineHemispherePdf(bs.wo);
    if (bs.pdf <= 0.0f) return Color3f(0.0f);
    bs.sampledFlags = BSDFFlags::DiffuseReflection;
    return reflectance_->eval(si);
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    if (Frame::cosTheta(si.wi) <= 0.0f || Frame::cosTheta(wo) <= 0.0f) return Color3f(0.0f);
    return reflectance_->eval(si) * (InvPi * Frame::cosTheta(wo));
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    if (Frame::cosTheta(si.wi) <= 0.0f) return 0.0f;
    return warp::squareToCosineHemispherePdf(wo);
  }

  std::string toString() const override { return str("DiffuseBSDF[reflectance=", reflectance_->toString(), "]"); }

 private:
  std::shared_ptr<Texture> reflectance_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::DiffuseBSDF, BSDF, "diffuse", "Lambertian (ideal diffuse) reflector")
