// difftrans: the ideal diffuse transmitter (Mitsuba 0.6's `difftrans`):
// light arriving on either side leaves from the other side with a
// Lambertian distribution, f = transmittance / pi for wi and wo on opposite
// sides, and nothing is reflected. Two-sided by nature (so `twosided` does
// not wrap it); a thin translucent sheet (paper, a lampshade). Sampled with
// the cosine-weighted hemisphere on the far side, so a sample's weight
// f |cos| / pdf is exactly the transmittance. Symmetric in wi and wo.
//
// | name          | type           | default | meaning                                  | unit |
// |---------------|----------------|---------|------------------------------------------|------|
// | transmittance | rgb or texture | 0.5     | diffuse transmittance (fraction passed)  | -    |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/bsdf.h>
#include <femto/render/texture.h>

namespace femto {

class DiffuseTransmitterBSDF final : public BSDF {
 public:
  explicit DiffuseTransmitterBSDF(const Properties& props)
      : transmittance_(textureOrColor(props, "transmittance", Color3f(0.5f))) {
    const Color3f mean = transmittance_->mean();
    for (int c = 0; c < 3; ++c)
      if (!(mean[c] >= 0.0f)) props.raise("transmittance", str("must not be negative, got ", mean));
  }

  uint32_t flags() const override { return BSDFFlags::DiffuseTransmission; }

  Color3f sample(const SurfaceInteraction& si, float, const Point2f& u2, BSDFSample& bs, TransportMode) const override {
    bs = BSDFSample();
    const float cosThetaI = Frame::cosTheta(si.wi);
    if (cosThetaI == 0.0f) return Color3f(0.0f);
    bs.wo = warp::squareToCosineHemisphere(u2);
    if (cosThetaI > 0.0f) bs.wo.z = -bs.wo.z;  // the side opposite wi
    bs.pdf = std::abs(Frame::cosTheta(bs.wo)) * InvPi;
    if (!(bs.pdf > 0.0f)) {
      bs.pdf = 0.0f;
      return Color3f(0.0f);
    }
    bs.sampledFlags = BSDFFlags::DiffuseTransmission;
    return transmittance_->eval(si);
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    if (!(Frame::cosTheta(si.wi) * Frame::cosTheta(wo) < 0.0f)) return Color3f(0.0f);
    return transmittance_->eval(si) * (InvPi * std::abs(Frame::cosTheta(wo)));
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    if (!(Frame::cosTheta(si.wi) * Frame::cosTheta(wo) < 0.0f)) return 0.0f;
    return std::abs(Frame::cosTheta(wo)) * InvPi;
  }

  std::string toString() const override {
    return str("DiffuseTransmitterBSDF[transmittance=", transmittance_->toString(), "]");
  }

 private:
  std::shared_ptr<Texture> transmittance_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::DiffuseTransmitterBSDF, BSDF, "difftrans", "Ideal diffuse transmitter")
