// roughdielectric: a rough interface between two dielectrics (frosted glass),
// the microfacet model of Walter et al. 2007 ("Microfacet Models for
// Refraction through Rough Surfaces"). With eta = int_ior / ext_ior and
// eta_t the index ratio (far side over near side) seen by wi:
//   reflection   f_r = F D G / (4 |cos i| |cos o|)                      (eq. 20)
//   transmission f_t = |i.m| |o.m| (1 - F) D G eta_t^2
//                      / (|cos i| |cos o| (i.m + eta_t o.m)^2)           (eq. 21)
// with the generalised half vector m ~ i + eta_t o (eq. 16), F the dielectric
// Fresnel term at i.m and G the separable Smith term. f_t is the BSDF for
// importance (light tracing); radiance (camera paths) is compressed on
// entering the denser side, so f_t is divided by eta_t^2 in Radiance mode
// (Veach 1997, sec. 5.2; as Mitsuba does). Sampling: a microfacet normal from
// the distribution, then reflection with probability F (eqs. 38-41; the
// Jacobians 1 / (4 |o.m|) and eta_t^2 |o.m| / (i.m + eta_t o.m)^2, eqs. 14
// and 17). Both sides of the surface scatter: the interior is on the -z
// side of the shading frame.
//
// | name                   | type             | default  | meaning                                          | unit |
// |------------------------|------------------|----------|--------------------------------------------------|------|
// | int_ior                | float or string  | bk7      | interior index of refraction (or a named material) | -  |
// | ext_ior                | float or string  | air      | exterior index of refraction                     | -    |
// | distribution           | string           | beckmann | "beckmann" or "ggx"                              | -    |
// | alpha                  | float            | 0.1      | isotropic roughness                              | -    |
// | alpha_u, alpha_v       | float            | 0.1      | anisotropic roughness (instead of alpha)         | -    |
// | sample_visible         | boolean          | true     | sample visible normals                           | -    |
// | specular_reflectance   | rgb or texture   | 1        | factor on reflection (not physical)              | -    |
// | specular_transmittance | rgb or texture   | 1        | factor on transmission (not physical)            | -    |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/fresnel.h>
#include <femto/scattering/ior.h>
#include <femto/scattering/microfacet.h>
#include <femto/transport/smooth_interface.h>
#include <femto/render/texture.h>

namespace femto {

class RoughDielectricBSDF final : public BSDF {
 public:
  explicit RoughDielectricBSDF(const Properties& props)
      : distribution_(MicrofacetDistribution::fromProperties(props)),
        specularReflectance_(textureOrColor(props, "specular_reflectance", Color3f(1.0f))),
        specularTransmittance_(textureOrColor(props, "specular_transmittance", Color3f(1.0f))) {
    IORPair ior = IORPair::read(props, *lookupIOR("bk7"));
    // Equal indices make the refracted lobe a delta (m ~ i - o vanishes):
    // not a rough interface at all.
    if (std::abs(ior.intIOR - ior.extIOR) < 1e-6f * ior.extIOR)
      props.raise("int_ior", str("int_ior and ext_ior are equal (", ior.intIOR,
                                 "): an index-matched boundary does not refract; use a \"null\" BSDF"));
    eta_ = ior.eta();
  }

  uint32_t flags() const override { return BSDFFlags::GlossyReflection | BSDFFlags::GlossyTransmission; }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    bs = BSDFSample();
    const Vec3f& wi = si.wi;
    float cosI = Frame::cosTheta(wi);
    if (cosI == 0.0f) return Color3f(0.0f);
    Vec3f m = distribution_.sample(wi, u2);
    float cosT;
    float F = fresnelDielectric(dot(wi, m), eta_, cosT);
    bool reflected = u1 < F;
    Vec3f wo = reflected ? reflect(wi, m) : refract(wi, m, cosT, eta_);
    // Directions on the wrong side of the surface and back-facing normals
    // are failed samples; pdf() excludes them.
    float weight = distribution_.sampleWeight(wi, wo, m);
    bool wrongSide = reflected ? Frame::cosTheta(wo) * cosI <= 0.0f : Frame::cosTheta(wo) * cosI >= 0.0f;
    if (wrongSide || weight <= 0.0f) return Color3f(0.0f);
    bs.wo = wo;
    bs.pdf = pdf(si, wo, mode);
    if (!(bs.pdf > 0.0f)) return Color3f(0.0f);
    if (reflected) {
      bs.sampledFlags = BSDFFlags::GlossyReflection;
      return specularReflectance_->eval(si) * weight;
    }
    float etaT = cosI > 0.0f ? eta_ : 1.0f / eta_;
    bs.sampledFlags = BSDFFlags::GlossyTransmission;
    bs.eta = etaT;
    float radianceScale = mode == TransportMode::Radiance ? 1.0f / (etaT * etaT) : 1.0f;
    return specularTransmittance_->eval(si) * (weight * radianceScale);
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    Geometry g;
    if (!geometry(si.wi, wo, g)) return Color3f(0.0f);
    float DG = distribution_.D(g.m) * distribution_.G(si.wi, wo, g.m);
    if (DG <= 0.0f) return Color3f(0.0f);
    float F = fresnelDielectric(g.iDotM, eta_);
    float absCosI = std::abs(Frame::cosTheta(si.wi));
    if (g.reflected) return specularReflectance_->eval(si) * (F * DG / (4.0f * absCosI));
    float value = std::abs(g.iDotM * g.oDotM) * (1.0f - F) * DG * g.etaT * g.etaT / (absCosI * g.denominator2);
    if (mode == TransportMode::Radiance) value /= g.etaT * g.etaT;
    return specularTransmittance_->eval(si) * value;
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    Geometry g;
    if (!geometry(si.wi, wo, g)) return 0.0f;
    float pdfM = distribution_.pdf(si.wi, g.m);
    float F = fresnelDielectric(g.iDotM, eta_);
    if (g.reflected) return F * pdfM / (4.0f * std::abs(g.oDotM));
    return (1.0f - F) * pdfM * g.etaT * g.etaT * std::abs(g.oDotM) / g.denominator2;
  }

  std::string toString() const override {
    return str("RoughDielectricBSDF[eta=", eta_, ", distribution=", distribution_.toString(),
               ", specular_reflectance=", specularReflectance_->toString(),
               ", specular_transmittance=", specularTransmittance_->toString(), "]");
  }

 private:
  /// The microfacet normal relating wi and wo, and what eval and pdf share.
  struct Geometry {
    Vec3f m;
    bool reflected = false;
    float etaT = 1.0f;          // index ratio, far side over wi's side (1 for reflection)
    float iDotM = 0, oDotM = 0;
    float denominator2 = 0;     // (i.m + eta_t o.m)^2, for transmission
  };

  /// False when no microfacet can scatter wi into wo: a direction in the
  /// tangent plane, or a normal some direction sees from behind (Walter's
  /// chi+ factors, which G also contains; checked here so pdf agrees).
  bool geometry(const Vec3f& wi, const Vec3f& wo, Geometry& g) const {
    float cosI = Frame::cosTheta(wi), cosO = Frame::cosTheta(wo);
    if (cosI == 0.0f || cosO == 0.0f) return false;
    g.reflected = cosI * cosO > 0.0f;
    g.etaT = g.reflected ? 1.0f : (cosI > 0.0f ? eta_ : 1.0f / eta_);
    Vec3f m = wi + wo * g.etaT;  // Walter eq. 16 (reflection: eq. 13)
    float len = length(m);
    if (!(len > 0.0f)) return false;
    g.m = m.z < 0.0f ? m / -len : m / len;  // the normal of the exterior side
    g.iDotM = dot(wi, g.m);
    g.oDotM = dot(wo, g.m);
    if (g.iDotM * cosI <= 0.0f || g.oDotM * cosO <= 0.0f) return false;
    float d = g.iDotM + g.etaT * g.oDotM;
    g.denominator2 = d * d;
    return g.reflected || g.denominator2 > 0.0f;
  }

  MicrofacetDistribution distribution_;
  float eta_ = 1.5f;
  std::shared_ptr<Texture> specularReflectance_, specularTransmittance_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::RoughDielectricBSDF, BSDF, "roughdielectric",
                    "rough dielectric interface (microfacet reflection and refraction, Walter et al. 2007)")
