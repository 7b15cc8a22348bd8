#pragma once
// What the BSDFs with a smooth dielectric interface (dielectric,
// thindielectric, plastic, and their rough variants) share: reading the two
// indices of refraction, and sampling the mirror direction.
#include <string>

#include <femto/core/properties.h>
#include <femto/render/bsdf.h>
#include <femto/render/ior.h>

namespace femto {

/// The interior and exterior indices of refraction (`int_ior`, `ext_ior`:
/// numbers or names from render/ior.h), with Mitsuba's exterior default "air".
struct IORPair {
  float intIOR = 1.0f, extIOR = 1.0f;

  static IORPair read(const Properties& props, float defaultIntIOR) {
    IORPair p;
    p.intIOR = iorFromProperties(props, "int_ior", defaultIntIOR);
    p.extIOR = iorFromProperties(props, "ext_ior", *lookupIOR("air"));
    return p;
  }
  /// Relative index interior over exterior, as render/fresnel.h expects.
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

}  // namespace femto
