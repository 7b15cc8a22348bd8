#pragma once
// What the BSDFs with a smooth dielectric interface (dielectric,
// thindielectric, plastic, and their rough variants) share: reading the two
// indices of refraction, and sampling the mirror direction.
#include <memory>
#include <string>

#include <femto/core/properties.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/ior.h>
#include <femto/render/texture.h>

namespace femto {

/// The interior and exterior indices of refraction (`int_ior`, `ext_ior`:
/// numbers or names from scattering/ior.h), with Mitsuba's exterior default "air".
struct IORPair {
  float intIOR = 1.0f, extIOR = 1.0f;

  static IORPair read(const Properties& props, float defaultIntIOR) {
    IORPair p;
    p.intIOR = iorFromProperties(props, "int_ior", defaultIntIOR);
    p.extIOR = iorFromProperties(props, "ext_ior", *lookupIOR("air"));
    return p;
  }
  /// Relative index interior over exterior, as scattering/fresnel.h expects.
  float eta() const { return intIOR / extIOR; }
  std::string toString() const { return str("int_ior=", intIOR, ", ext_ior=", extIOR); }
};

/// Sets `bs` to the mirror reflection of si.wi about the normal (+z),
/// chosen with probability `probability`.
inline void sampleDeltaReflection(const SurfaceInteraction& si, float probability, BSDFSample& bs) {
  bs = BSDFSample();
  bs.wo = reflect(si.wi, Vec3f(0, 0, 1));
  bs.pdf = probability;
  bs.sampledFlags = BSDFFlags::DeltaReflection;
}

/// Base of the purely specular dielectrics (dielectric, thindielectric): both
/// read the same parameters (int_ior/ext_ior, default bk7 in air;
/// specular_reflectance and specular_transmittance) and have only delta
/// components, so nothing to evaluate for a given pair of directions.
class SpecularDielectricBSDF : public BSDF {
 public:
  explicit SpecularDielectricBSDF(const Properties& props)
      : iors_(IORPair::read(props, *lookupIOR("bk7"))),
        eta_(iors_.eta()),
        reflectance_(textureOrColor(props, "specular_reflectance", Color3f(1.0f))),
        transmittance_(textureOrColor(props, "specular_transmittance", Color3f(1.0f))) {}

  uint32_t flags() const override { return BSDFFlags::DeltaReflection | BSDFFlags::DeltaTransmission; }
  Color3f eval(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return Color3f(0.0f); }
  float pdf(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return 0.0f; }

 protected:
  /// "Name[int_ior=..., ext_ior=..., specular_reflectance=..., specular_transmittance=...]".
  std::string describe(const char* name) const {
    return str(name, "[", iors_.toString(), ", specular_reflectance=", reflectance_->toString(),
               ", specular_transmittance=", transmittance_->toString(), "]");
  }

  IORPair iors_;
  float eta_;  // iors_.eta()
  std::shared_ptr<Texture> reflectance_, transmittance_;
};

}  // namespace femto
