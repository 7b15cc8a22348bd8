// dielectric: a smooth boundary between two dielectrics (glass, water),
// reflecting and refracting in the two delta directions given by the law of
// reflection and Snell's law, in the proportions given by the unpolarised
// Fresnel equations. sample() picks one of the two by the Fresnel
// reflectance, so a sample's weight is just the reflectance/transmittance
// factor (Mitsuba 3's `dielectric`; pbrt-v4 sec. 9.5).
//
// Radiance crossing into a denser medium is compressed into a narrower solid
// angle: in Radiance transport the transmitted weight carries 1/eta_it^2
// (Veach 1997, sec. 5.2, "non-symmetric scattering due to refraction"); in
// Importance transport it does not. BSDFSample::eta is eta_it, the index
// ratio (other side over incident side) of the crossing.
//
// | name                   | type            | default | meaning                                        | unit |
// |------------------------|-----------------|---------|------------------------------------------------|------|
// | int_ior                | float or string | "bk7"   | interior index of refraction (or material name) | -    |
// | ext_ior                | float or string | "air"   | exterior index of refraction (or material name) | -    |
// | specular_reflectance   | rgb or texture  | 1       | scale of the reflected part (not physical)     | -    |
// | specular_transmittance | rgb or texture  | 1       | scale of the transmitted part (not physical)   | -    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/fresnel.h>
#include <femto/transport/smooth_interface.h>
#include <femto/render/texture.h>

namespace femto {

class DielectricBSDF final : public SpecularDielectricBSDF {
 public:
  explicit DielectricBSDF(const Properties& props) : SpecularDielectricBSDF(props) {}

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f&, BSDFSample& bs,
                 TransportMode mode) const override {
    bs = BSDFSample();
    const float cosThetaI = Frame::cosTheta(si.wi);
    float cosThetaT;
    const float r = fresnelDielectric(cosThetaI, eta_, cosThetaT);
    if (u1 < r) {  // reflect, with probability R: weight R / R
      sampleDeltaReflection(si, r, bs);
      return reflectance_->eval(si);
    }
    // Refract, with probability 1 - R: weight (1 - R) / (1 - R), times the radiance scaling.
    const float etaIT = cosThetaI >= 0.0f ? eta_ : 1.0f / eta_;
    bs.wo = refract(si.wi, cosThetaT, eta_);
    bs.pdf = 1.0f - r;
    bs.eta = etaIT;
    bs.sampledFlags = BSDFFlags::DeltaTransmission;
    Color3f weight = transmittance_->eval(si);
    if (mode == TransportMode::Radiance) weight *= 1.0f / (etaIT * etaIT);
    return weight;
  }

  std::string toString() const override { return describe("DielectricBSDF"); }

};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::DielectricBSDF, BSDF, "dielectric", "Smooth dielectric boundary (glass, water)")
