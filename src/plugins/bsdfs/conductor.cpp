// conductor: a smooth metal, a perfect specular reflector whose reflectance
// is the exact unpolarised Fresnel reflectance of a conductor with complex
// index of refraction eta + i k (render/fresnel.h). The optical constants come
// from a named material (RGB table in render/fresnel.cpp; "none" is an ideal
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
#include <femto/core/spelling.h>
#include <femto/render/bsdf.h>
#include <femto/render/fresnel.h>
#include <femto/render/smooth_interface.h>
#include <femto/render/texture.h>

namespace femto {
namespace {

/// A non-negative colour parameter (eta or k), with file:line on error.
Color3f nonNegativeColor(const Properties& props, const std::string& name) {
  Color3f c = props.getColor(name);
  if (!(c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f))
    props.raise(name, str("must not be negative, got ", c));
  return c;
}

}  // namespace

class ConductorBSDF final : public BSDF {
 public:
  explicit ConductorBSDF(const Properties& props)
      : reflectance_(textureOrColor(props, "specular_reflectance", Color3f(1.0f))) {
    readOpticalConstants(props);
    // The Fresnel equations depend on the index relative to the exterior.
    const float extEta = iorFromProperties(props, "ext_eta", 1.0f);
    eta_ = eta_ / extEta;
    k_ = k_ / extEta;
  }

  uint32_t flags() const override { return BSDFFlags::DeltaReflection; }

  Color3f sample(const SurfaceInteraction& si, float, const Point2f&, BSDFSample& bs, TransportMode) const override {
    bs = BSDFSample();
    const float cosThetaI = Frame::cosTheta(si.wi);
    if (cosThetaI <= 0.0f) return Color3f(0.0f);
    sampleDeltaReflection(si, 1.0f, bs);
    return reflectance_->eval(si) * fresnelConductor(cosThetaI, eta_, k_);
  }

  Color3f eval(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return Color3f(0.0f); }
  float pdf(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return 0.0f; }

  std::string toString() const override {
    return str("ConductorBSDF[material=", material_, ", eta=", eta_, ", k=", k_,
               ", specular_reflectance=", reflectance_->toString(), "]");
  }

 private:
  /// eta and k from `material` (default "none") or from explicit eta and k.
  void readOpticalConstants(const Properties& props) {
    const bool hasEta = props.has("eta"), hasK = props.has("k");
    if (hasEta || hasK) {
      if (props.has("material"))
        props.raise("material", "give either a material name or eta and k, not both");
      if (!hasEta || !hasK) props.raise(hasEta ? "eta" : "k", "eta and k must be given together");
      eta_ = nonNegativeColor(props, "eta");
      k_ = nonNegativeColor(props, "k");
      material_ = "custom";
      return;
    }
    material_ = props.getString("material", "none");
    auto constants = lookupConductor(material_);
    if (!constants)
      props.raise("material", str("unknown conductor \"", material_, "\"", didYouMean(material_, knownConductorNames()),
                                  "; give eta and k for other metals"));
    eta_ = constants->first;
    k_ = constants->second;
  }

  std::string material_;
  Color3f eta_, k_;
  std::shared_ptr<Texture> reflectance_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ConductorBSDF, BSDF, "conductor", "Smooth metal (Fresnel conductor mirror)")
