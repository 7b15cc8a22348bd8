// plastic: a diffuse base under a smooth dielectric coating (Mitsuba 3's
// `plastic`, after Weidlich & Wilkie 2007, "Arbitrarily layered micro-facet
// surfaces"). Light either reflects specularly off the coating (Fresnel
// reflectance R(wi)) or enters it, scatters in the diffuse base, possibly
// bouncing between base and coating many times, and leaves diffusely:
//
//   f_diffuse(wi, wo) = (1 - R(wi)) (1 - R(wo)) / (pi eta^2) * rho / (1 - F_int x),
//
// with F_int = fresnelDiffuseReflectance(1/eta) the fraction of diffuse light
// the coating reflects back down, and x = rho ("nonlinear": the inner
// bounces tint the colour, as on wet or varnished surfaces) or x = 1 (the
// default: rho is the albedo the surface appears to have). 1/eta^2 is the
// radiance expansion of light leaving the denser coating. The expression is
// symmetric in wi and wo, so the BSDF is reciprocal.
//
// Sampling picks the specular lobe with probability proportional to
// R(wi) * s against (1 - R(wi)) * (1 - s), where s = mean(specular) /
// (mean(specular) + mean(diffuse)) (Mitsuba's specular sampling weight), and
// the diffuse lobe with cosine-weighted hemisphere sampling. One-sided.
//
// | name                 | type            | default         | meaning                                       | unit |
// |----------------------|-----------------|-----------------|-----------------------------------------------|------|
// | int_ior              | float or string | "polypropylene" | coating index of refraction (1.49) or name    | -    |
// | ext_ior              | float or string | "air"           | exterior index of refraction or name          | -    |
// | specular_reflectance | rgb or texture  | 1               | scale of the specular reflection (not physical) | -  |
// | diffuse_reflectance  | rgb or texture  | 0.5             | albedo of the diffuse base                    | -    |
// | nonlinear            | boolean         | false           | account for colour shifts of inner bounces    | -    |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/fresnel.h>
#include <femto/transport/smooth_interface.h>
#include <femto/render/texture.h>

namespace femto {

class PlasticBSDF final : public BSDF {
 public:
  explicit PlasticBSDF(const Properties& props)
      : iors_(IORPair::read(props, *lookupIOR("polypropylene"))),
        eta_(iors_.eta()),
        specular_(textureOrColor(props, "specular_reflectance", Color3f(1.0f))),
        diffuse_(textureOrColor(props, "diffuse_reflectance", Color3f(0.5f))),
        nonlinear_(props.getBool("nonlinear", false)),
        fdrInternal_(fresnelDiffuseReflectance(1.0f / eta_)) {
    const float specularMean = specular_->mean().average(), diffuseMean = diffuse_->mean().average();
    if (!(specularMean >= 0.0f)) props.raise("specular_reflectance", "must not be negative");
    if (!(diffuseMean >= 0.0f)) props.raise("diffuse_reflectance", "must not be negative");
    const float total = specularMean + diffuseMean;
    specularSamplingWeight_ = total > 0.0f ? specularMean / total : 0.5f;
  }

  uint32_t flags() const override { return BSDFFlags::DeltaReflection | BSDFFlags::DiffuseReflection; }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    bs = BSDFSample();
    const float cosThetaI = Frame::cosTheta(si.wi);
    if (cosThetaI <= 0.0f) return Color3f(0.0f);
    const float r = fresnelDielectric(cosThetaI, eta_);
    const float pSpecular = specularProbability(r);
    if (u1 < pSpecular) {
      sampleDeltaReflection(si, pSpecular, bs);
      return specular_->eval(si) * (r / pSpecular);
    }
    bs.wo = warp::squareToCosineHemisphere(u2);
    bs.pdf = (1.0f - pSpecular) * warp::squareToCosineHemispherePdf(bs.wo);
    if (!(bs.pdf > 0.0f)) {
      bs.pdf = 0.0f;
      return Color3f(0.0f);
    }
    bs.sampledFlags = BSDFFlags::DiffuseReflection;
    return eval(si, bs.wo, mode) / bs.pdf;
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    const float cosThetaI = Frame::cosTheta(si.wi), cosThetaO = Frame::cosTheta(wo);
    if (cosThetaI <= 0.0f || cosThetaO <= 0.0f) return Color3f(0.0f);
    const float ti = 1.0f - fresnelDielectric(cosThetaI, eta_), to = 1.0f - fresnelDielectric(cosThetaO, eta_);
    const Color3f rho = diffuse_->eval(si);
    Color3f base;
    for (int c = 0; c < 3; ++c) base[c] = rho[c] / (1.0f - fdrInternal_ * (nonlinear_ ? rho[c] : 1.0f));
    return base * (ti * to * cosThetaO * InvPi / (eta_ * eta_));
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    const float cosThetaI = Frame::cosTheta(si.wi);
    if (cosThetaI <= 0.0f || Frame::cosTheta(wo) <= 0.0f) return 0.0f;
    const float pSpecular = specularProbability(fresnelDielectric(cosThetaI, eta_));
    return (1.0f - pSpecular) * warp::squareToCosineHemispherePdf(wo);
  }

  std::string toString() const override {
    return str("PlasticBSDF[", iors_.toString(), ", specular_reflectance=", specular_->toString(),
               ", diffuse_reflectance=", diffuse_->toString(), ", nonlinear=", nonlinear_ ? "true" : "false", "]");
  }

 private:
  /// Probability of sampling the specular lobe given the coating's reflectance r at wi.
  float specularProbability(float r) const {
    const float s = r * specularSamplingWeight_, d = (1.0f - r) * (1.0f - specularSamplingWeight_);
    return s + d > 0.0f ? s / (s + d) : 0.0f;
  }

  IORPair iors_;
  float eta_;
  std::shared_ptr<Texture> specular_, diffuse_;
  bool nonlinear_;
  float fdrInternal_;
  float specularSamplingWeight_ = 0.5f;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::PlasticBSDF, BSDF, "plastic", "Smooth dielectric coating over a diffuse base")
