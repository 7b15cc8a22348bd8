// isotropic: scatters uniformly over the sphere, p = 1 / (4 pi). Sampled
// exactly, so every sample has weight 1. Reads the scattering delay
// parameters of every phase function (render/phase.h: delay, lifetime).
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/phase.h>

namespace femto {

class IsotropicPhase final : public PhaseFunction {
 public:
  explicit IsotropicPhase(const Properties& props) : PhaseFunction(props) {}

  float eval(const Vec3f&, const Vec3f&) const override { return Inv4Pi; }

  float sample(const Vec3f&, const Point2f& u, Vec3f& wo, float& pdf) const override {
    wo = warp::squareToUniformSphere(u);
    pdf = Inv4Pi;
    return 1.0f;
  }

  float pdf(const Vec3f&, const Vec3f&) const override { return Inv4Pi; }

  std::string toString() const override { return str("IsotropicPhase[", delayString(), "]"); }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::IsotropicPhase, PhaseFunction, "isotropic", "Isotropic phase function")
