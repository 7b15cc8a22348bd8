// thindielectric: a thin pane of glass with two parallel, smooth faces, so
// close together that the light leaves where it entered. Transmitted light
// goes straight through (no refraction offset); the reflectance sums the
// series of internal reflections inside the pane,
//   R' = R + T^2 R (1 + R^2 + R^4 + ...) = R + T^2 R / (1 - R^2),  T' = 1 - R',
// with R the single-interface Fresnel reflectance and T = 1 - R
// (Mitsuba 3's `thindielectric`; absorption inside the pane is ignored).
// Both faces behave alike, so the BSDF is the same from either side.
//
// | name                   | type            | default | meaning                                        | unit |
// |------------------------|-----------------|---------|------------------------------------------------|------|
// | int_ior                | float or string | "bk7"   | index of refraction of the pane (or name)      | -    |
// | ext_ior                | float or string | "air"   | index of the surrounding medium (or name)      | -    |
// | specular_reflectance   | rgb or texture  | 1       | scale of the reflected part (not physical)     | -    |
// | specular_transmittance | rgb or texture  | 1       | scale of the transmitted part (not physical)   | -    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/fresnel.h>
#include <femto/transport/smooth_interface.h>
#include <femto/render/texture.h>

namespace femto {

class ThinDielectricBSDF final : public SpecularDielectricBSDF {
 public:
  explicit ThinDielectricBSDF(const Properties& props) : SpecularDielectricBSDF(props) {}

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f&, BSDFSample& bs,
                 TransportMode) const override {
    bs = BSDFSample();
    const float r = paneReflectance(std::abs(Frame::cosTheta(si.wi)));
    if (u1 < r) {
      sampleDeltaReflection(si, r, bs);
      return reflectance_->eval(si);
    }
    // Straight through: both faces refract, and undo each other's radiance scaling.
    bs.wo = -si.wi;
    bs.pdf = 1.0f - r;
    bs.sampledFlags = BSDFFlags::DeltaTransmission;
    return transmittance_->eval(si);
  }

  std::string toString() const override { return describe("ThinDielectricBSDF"); }

 private:
  /// Reflectance of the pane, internal reflections included (see the header comment).
  float paneReflectance(float cosThetaI) const {
    const float r = fresnelDielectric(cosThetaI, eta_);
    if (r >= 1.0f) return 1.0f;  // only at exactly grazing incidence
    const float t = 1.0f - r;
    return r + t * t * r / (1.0f - r * r);
  }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ThinDielectricBSDF, BSDF, "thindielectric", "Thin dielectric pane (window glass)")
