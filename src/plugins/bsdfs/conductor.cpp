// conductor: a smooth metal, a perfect specular reflector whose reflectance
// is the exact unpolarised Fresnel reflectance of a conductor with complex
// index of refraction eta + i k (scattering/fresnel.h). The optical constants come
// from a named material (RGB table in scattering/fresnel.cpp; "none" is an ideal
// mirror) or are given directly. One-sided, as in Mitsuba: light from below
// the shading surface is absorbed.
//
// | name                 | type            | default | meaning                                                             | unit |
// |----------------------|-----------------|---------|---------------------------------------------------------------------|------|
// | material             | string          | "none"  | named metal ("Au", "Ag", "Al", "Cu", ...)                           | -    |
// | eta                  | rgb or float    | -       | real part of the index (instead of material; needs k)               | -    |
// | k                    | rgb or float    | -       | imaginary part, the extinction coefficient (needs eta)              | -    |
// | ext_eta              | float or string | 1       | exterior index (Mitsuba 0.6's extEta); eta and k are relative to it | -    |
// | specular_reflectance | rgb or texture  | 1       | scale of the reflectance (not physical)                             | -    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/conductor_ior.h>
#include <femto/scattering/fresnel.h>
#include <femto/transport/smooth_interface.h>
#include <femto/render/texture.h>

namespace femto {

class ConductorBSDF final : public BSDF {
 public:
  explicit ConductorBSDF(const Properties& props)
      : ior_(conductorIORFromProperties(props)),
        reflectance_(textureOrColor(props, "specular_reflectance", Color3f(1.0f))) {}

  uint32_t flags() const override { return BSDFFlags::DeltaReflection; }

  Color3f sample(const SurfaceInteraction& si, float, const Point2f&, BSDFSample& bs, TransportMode) const override {
    bs = BSDFSample();
    const float cosThetaI = Frame::cosTheta(si.wi);
    if (cosThetaI <= 0.0f) return Color3f(0.0f);
    sampleDeltaReflection(si, 1.0f, bs);
    return reflectance_->eval(si) * fresnelConductor(cosThetaI, ior_.eta, ior_.k);
  }

  Color3f eval(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return Color3f(0.0f); }
  float pdf(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return 0.0f; }

  std::string toString() const override {
    return str("ConductorBSDF[material=", ior_.material, ", eta=", ior_.eta, ", k=", ior_.k,
               ", specular_reflectance=", reflectance_->toString(), "]");
  }

 private:
  ConductorIOR ior_;
  std::shared_ptr<Texture> reflectance_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ConductorBSDF, BSDF, "conductor", "Smooth metal (Fresnel conductor mirror)")
