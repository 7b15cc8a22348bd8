// roughplastic: a diffuse base under a rough dielectric coating, Mitsuba's
// model (Mitsuba 0.6 and 3 "roughplastic"; the smooth-coating version is
// Weidlich & Wilkie 2007, "Arbitrarily Layered Micro-Facet Surfaces"). It is
// an approximation, not a simulation of the layer:
//
//   f = f_spec + f_diff,
//   f_spec = R_s F(wi.h) D(h) G(wi, wo, h) / (4 cos i cos o)
//            (microfacet reflection off the coating, Walter et al. 2007),
//   f_diff = T(cos i) T(cos o) / eta^2 * rho / (pi (1 - X F_int)),
//            X = 1 (linear) or rho (nonlinear),
//
// where T(mu) = 1 - (albedo of the rough coating's reflection seen from
// outside at cos theta = mu) is the energy the coating lets into the layer,
// and F_int is the cosine-weighted average of the coating's reflection
// albedo seen from inside (index ratio 1 / eta): diffuse light bounces
// between base and coating, a geometric series summed in closed form. 1 /
// eta^2 is the radiance compression of light leaving the denser layer. As
// Mitsuba 3 does, T and F_int are computed when the plugin is created, by
// quadrature over the visible normals (the albedo of microfacet reflection
// is E[F(wi.m) G1(wo, m)] under D_wi, Heitz & d'Eon 2014); energy the Smith
// term loses at the coating counts as transmitted (T = 1 - reflected).
// Sampling picks the coating's lobe or the cosine-weighted diffuse lobe with
// probabilities proportional to (1 - T(cos i)) s and T(cos i) (1 - s), s =
// mean(R_s) / (mean(R_s) + mean(rho)). One-sided; isotropic only (as in
// Mitsuba).
//
// | name                 | type            | default       | meaning                                      | unit |
// |----------------------|-----------------|---------------|----------------------------------------------|------|
// | diffuse_reflectance  | rgb or texture  | 0.5           | albedo rho of the diffuse base               | -    |
// | specular_reflectance | rgb or texture  | 1             | factor R_s on the coating's reflection (keep 1 to be physical) | - |
// | int_ior              | float or string | polypropylene | index of refraction of the coating (1.49)    | -    |
// | ext_ior              | float or string | air           | index of refraction outside                  | -    |
// | nonlinear            | boolean         | false         | account for the colour shift of repeated diffuse bounces | - |
// | distribution         | string          | beckmann      | "beckmann" or "ggx"                          | -    |
// | alpha                | float           | 0.1           | roughness of the coating                     | -    |
// | sample_visible       | boolean         | true          | sample visible normals                       | -    |
#include <array>
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/fresnel.h>
#include <femto/scattering/ior.h>
#include <femto/scattering/microfacet.h>
#include <femto/transport/smooth_interface.h>
#include <femto/render/texture.h>

namespace femto {
namespace {

constexpr int TableSize = 64;        // cos(theta) nodes of the coating's transmittance, as Mitsuba 3
constexpr int QuadratureSize = 24;   // per-axis midpoint nodes over the visible normals' unit square

/// Directional albedo of microfacet reflection off a dielectric of relative
/// index `eta`, for incidence cos(theta) = mu: E[F(wi.m) G1(wo, m)] for m
/// following D_wi (the rest of f cos / pdf cancels), by the midpoint rule
/// over the sampler's unit square (the visible-normal warps are smooth).
float reflectionAlbedo(const MicrofacetDistribution& visible, float mu, float eta) {
  Vec3f wi(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
  double sum = 0.0;
  for (int j = 0; j < QuadratureSize; ++j)
    for (int i = 0; i < QuadratureSize; ++i) {
      Point2f u((i + 0.5f) / QuadratureSize, (j + 0.5f) / QuadratureSize);
      Vec3f m = visible.sample(wi, u);
      Vec3f wo = reflect(wi, m);
      if (wo.z <= 0.0f) continue;
      sum += fresnelDielectric(dot(wi, m), eta) * visible.sampleWeight(wi, wo, m);
    }
  return float(sum / (QuadratureSize * QuadratureSize));
}

float tableCosine(int i) { return std::max(1e-4f, float(i) / (TableSize - 1)); }

/// Linear interpolation in a table over cos(theta) in [0, 1].
float lookup(const std::array<float, TableSize>& table, float mu) {
  float x = std::clamp(mu, 0.0f, 1.0f) * (TableSize - 1);
  int i = std::min(int(x), TableSize - 2);
  float t = x - i;
  return (1.0f - t) * table[i] + t * table[i + 1];
}

}  // namespace

class RoughPlasticBSDF final : public BSDF {
 public:
  explicit RoughPlasticBSDF(const Properties& props)
      : distribution_(MicrofacetDistribution::fromProperties(props, /*allowAnisotropic=*/false)),
        diffuseReflectance_(textureOrColor(props, "diffuse_reflectance", Color3f(0.5f))),
        specularReflectance_(textureOrColor(props, "specular_reflectance", Color3f(1.0f))),
        nonlinear_(props.getBool("nonlinear", false)) {
    eta_ = IORPair::read(props, *lookupIOR("polypropylene")).eta();

    MicrofacetDistribution visible = distribution_.withSampleVisible(true);
    std::array<float, TableSize> internalReflectance;
    for (int i = 0; i < TableSize; ++i) {
      externalTransmittance_[i] = 1.0f - reflectionAlbedo(visible, tableCosine(i), eta_);
      internalReflectance[i] = reflectionAlbedo(visible, tableCosine(i), 1.0f / eta_);
    }
    // F_int = 2 integral_0^1 R(mu) mu dmu, trapezoidal rule on the table.
    double integral = 0.0;
    for (int i = 0; i + 1 < TableSize; ++i) {
      float mu0 = tableCosine(i), mu1 = tableCosine(i + 1);
      integral += 0.5 * (internalReflectance[i] * mu0 + internalReflectance[i + 1] * mu1) * (mu1 - mu0);
    }
    internalReflectance_ = float(2.0 * integral);

    float specularMean = specularReflectance_->mean().average(), diffuseMean = diffuseReflectance_->mean().average();
    specularSamplingWeight_ = specularMean + diffuseMean > 0.0f ? specularMean / (specularMean + diffuseMean) : 0.5f;
  }

  uint32_t flags() const override { return BSDFFlags::GlossyReflection | BSDFFlags::DiffuseReflection; }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    bs = BSDFSample();
    const Vec3f& wi = si.wi;
    if (Frame::cosTheta(wi) <= 0.0f) return Color3f(0.0f);
    bool specular = u1 < specularProbability(Frame::cosTheta(wi));
    if (specular) {
      Vec3f m = distribution_.sample(wi, u2);
      if (dot(wi, m) <= 0.0f) return Color3f(0.0f);  // a back-facing normal: pdf() excludes these
      bs.wo = reflect(wi, m);
    } else {
      bs.wo = warp::squareToCosineHemisphere(u2);
    }
    if (Frame::cosTheta(bs.wo) <= 0.0f) return Color3f(0.0f);
    bs.pdf = pdf(si, bs.wo, mode);
    if (!(bs.pdf > 0.0f)) return Color3f(0.0f);
    bs.sampledFlags = specular ? BSDFFlags::GlossyReflection : BSDFFlags::DiffuseReflection;
    return eval(si, bs.wo, mode) / bs.pdf;
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    const Vec3f& wi = si.wi;
    float cosI = Frame::cosTheta(wi), cosO = Frame::cosTheta(wo);
    if (cosI <= 0.0f || cosO <= 0.0f) return Color3f(0.0f);
    Vec3f h = normalize(wi + wo);
    float spec = fresnelDielectric(dot(wi, h), eta_) * distribution_.D(h) * distribution_.G(wi, wo, h) / (4.0f * cosI);
    Color3f rho = diffuseReflectance_->eval(si);
    Color3f multipleBounces = Color3f(1.0f) - (nonlinear_ ? rho * internalReflectance_ : Color3f(internalReflectance_));
    float transmission = lookup(externalTransmittance_, cosI) * lookup(externalTransmittance_, cosO) / (eta_ * eta_);
    return specularReflectance_->eval(si) * spec + rho / multipleBounces * (transmission * InvPi * cosO);
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    const Vec3f& wi = si.wi;
    float cosI = Frame::cosTheta(wi), cosO = Frame::cosTheta(wo);
    if (cosI <= 0.0f || cosO <= 0.0f) return 0.0f;
    Vec3f h = normalize(wi + wo);
    float specularPdf = distribution_.pdf(wi, h) / (4.0f * dot(wo, h));
    float p = specularProbability(cosI);
    return p * specularPdf + (1.0f - p) * warp::squareToCosineHemispherePdf(wo);
  }

  std::string toString() const override {
    return str("RoughPlasticBSDF[eta=", eta_, ", distribution=", distribution_.toString(),
               ", diffuse_reflectance=", diffuseReflectance_->toString(),
               ", specular_reflectance=", specularReflectance_->toString(),
               ", nonlinear=", nonlinear_ ? "true" : "false", "]");
  }

 private:
  /// Probability of sampling the coating's lobe for incidence cos(theta_i).
  float specularProbability(float cosI) const {
    float t = lookup(externalTransmittance_, cosI);
    float specular = (1.0f - t) * specularSamplingWeight_, diffuse = t * (1.0f - specularSamplingWeight_);
    return specular + diffuse > 0.0f ? specular / (specular + diffuse) : 0.0f;
  }

  MicrofacetDistribution distribution_;
  std::shared_ptr<Texture> diffuseReflectance_, specularReflectance_;
  bool nonlinear_;
  float eta_ = 1.49f;
  std::array<float, TableSize> externalTransmittance_{};
  float internalReflectance_ = 0.0f;
  float specularSamplingWeight_ = 0.5f;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::RoughPlasticBSDF, BSDF, "roughplastic",
                    "diffuse base under a rough dielectric coating (Mitsuba's approximation)")
