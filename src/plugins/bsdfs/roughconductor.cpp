// roughconductor: a rough metal, the microfacet reflection model of Walter et
// al. 2007 ("Microfacet Models for Refraction through Rough Surfaces", eq.
// 20) with the exact conductor Fresnel term:
//   f(wi, wo) = R F(wi.h) D(h) G(wi, wo, h) / (4 cos(theta_i) cos(theta_o)),
// h the half vector. One-sided like Mitsuba's: light below the shading
// surface is absorbed. Sampled through the visible normals (or D cos) of the
// microfacet distribution (scattering/microfacet.h).
//
// | name                 | type           | default  | meaning                                                   | unit |
// |----------------------|----------------|----------|-----------------------------------------------------------|------|
// | distribution         | string         | beckmann | "beckmann" or "ggx"                                       | -    |
// | alpha                | float          | 0.1      | isotropic roughness (Beckmann: RMS slope)                 | -    |
// | alpha_u, alpha_v     | float          | 0.1      | anisotropic roughness along tangent / bitangent (instead of alpha) | - |
// | sample_visible       | boolean        | true     | sample visible normals (Heitz 2018 / Heitz & d'Eon 2014)  | -    |
// | material             | string         | none     | named conductor ("Au", "Cu", ...; "none": perfect mirror) | -    |
// | eta, k               | rgb or float   | -        | complex index of refraction eta + ik (together, instead of material) | - |
// | ext_eta              | float or string | 1       | exterior index (Mitsuba 0.6's extEta); eta and k are relative to it | - |
// | specular_reflectance | rgb or texture | 1        | factor on the reflectance (not physical; for artists)     | -    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/conductor_ior.h>
#include <femto/scattering/fresnel.h>
#include <femto/scattering/microfacet.h>
#include <femto/render/texture.h>

namespace femto {

class RoughConductorBSDF final : public BSDF {
 public:
  explicit RoughConductorBSDF(const Properties& props)
      : distribution_(MicrofacetDistribution::fromProperties(props)),
        ior_(conductorIORFromProperties(props)),
        specularReflectance_(textureOrColor(props, "specular_reflectance", Color3f(1.0f))) {}

  uint32_t flags() const override { return BSDFFlags::GlossyReflection; }

  Color3f sample(const SurfaceInteraction& si, float, const Point2f& u2, BSDFSample& bs,
                 TransportMode) const override {
    bs = BSDFSample();
    const Vec3f& wi = si.wi;
    if (Frame::cosTheta(wi) <= 0.0f) return Color3f(0.0f);
    Vec3f m = distribution_.sample(wi, u2);
    Vec3f wo = reflect(wi, m);
    // Reflections below the horizon, and back-facing normals (only drawn
    // without visible sampling), are failed samples: pdf() excludes them.
    float weight = distribution_.sampleWeight(wi, wo, m);
    if (Frame::cosTheta(wo) <= 0.0f || weight <= 0.0f) return Color3f(0.0f);
    bs.wo = wo;
    bs.pdf = distribution_.pdf(wi, m) / (4.0f * dot(wo, m));
    bs.sampledFlags = BSDFFlags::GlossyReflection;
    if (!(bs.pdf > 0.0f)) return Color3f(0.0f);
    return specularReflectance_->eval(si) * fresnelConductor(dot(wi, m), ior_.eta, ior_.k) * weight;
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    const Vec3f& wi = si.wi;
    float cosI = Frame::cosTheta(wi), cosO = Frame::cosTheta(wo);
    if (cosI <= 0.0f || cosO <= 0.0f) return Color3f(0.0f);
    Vec3f h = normalize(wi + wo);
    float DG = distribution_.D(h) * distribution_.G(wi, wo, h);
    if (DG <= 0.0f) return Color3f(0.0f);
    return specularReflectance_->eval(si) * fresnelConductor(dot(wi, h), ior_.eta, ior_.k) * (DG / (4.0f * cosI));
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    const Vec3f& wi = si.wi;
    if (Frame::cosTheta(wi) <= 0.0f || Frame::cosTheta(wo) <= 0.0f) return 0.0f;
    Vec3f h = normalize(wi + wo);
    // Jacobian of the reflection h -> wo: 1 / (4 wo.h) (Walter eq. 14).
    return distribution_.pdf(wi, h) / (4.0f * dot(wo, h));
  }

  std::string toString() const override {
    return str("RoughConductorBSDF[material=", ior_.material, ", eta=", ior_.eta, ", k=", ior_.k,
               ", distribution=", distribution_.toString(),
               ", specular_reflectance=", specularReflectance_->toString(), "]");
  }

 private:
  MicrofacetDistribution distribution_;
  ConductorIOR ior_;
  std::shared_ptr<Texture> specularReflectance_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::RoughConductorBSDF, BSDF, "roughconductor", "rough metal (microfacet reflection, Walter et al. 2007)")
