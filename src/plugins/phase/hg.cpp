// hg: the Henyey-Greenstein phase function (Henyey & Greenstein 1941),
//   p(theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)),
// where theta is the angle between the propagation directions before and
// after scattering (cos theta = -dot(wi, wo) with phase.h's convention: both
// directions point away from the scattering point). g > 0 scatters forward.
// Sampled exactly by inverting its CDF in cos theta (pbrt-v3, sec. 15.2.3),
// so every sample has weight 1. Also reads delay/lifetime (render/phase.h).
//
// | name | type  | default | meaning                                          | unit |
// |------|-------|---------|--------------------------------------------------|------|
// | g    | float | 0.8     | mean cosine of the scattering angle, in (-1, 1)  | -    |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/math/frame.h>
#include <femto/render/phase.h>

namespace femto {

class HGPhase final : public PhaseFunction {
 public:
  explicit HGPhase(const Properties& props) : PhaseFunction(props), g_(props.getFloat("g", 0.8f, Range::open(-1, 1))) {
  }

  float eval(const Vec3f& wi, const Vec3f& wo) const override { return density(-dot(wi, wo)); }

  float sample(const Vec3f& wi, const Point2f& u, Vec3f& wo, float& pdf) const override {
    // Inverse CDF of cos theta; the isotropic limit avoids dividing by g ~ 0.
    float cosTheta;
    if (std::abs(g_) < 1e-3f) {
      cosTheta = 1.0f - 2.0f * u.x;
    } else {
      float sq = (1.0f - g_ * g_) / (1.0f - g_ + 2.0f * g_ * u.x);
      cosTheta = (1.0f + g_ * g_ - sq * sq) / (2.0f * g_);
    }
    cosTheta = std::clamp(cosTheta, -1.0f, 1.0f);
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = 2.0f * Pi * u.y;
    // theta is measured from the propagation direction -wi.
    Frame frame(-wi);
    wo = frame.toWorld(Vec3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
    pdf = density(cosTheta);
    return 1.0f;
  }

  float pdf(const Vec3f& wi, const Vec3f& wo) const override { return eval(wi, wo); }

  std::string toString() const override { return str("HGPhase[g=", g_, delayString(), "]"); }

 private:
  float density(float cosTheta) const {
    float denom = 1.0f + g_ * g_ - 2.0f * g_ * cosTheta;
    return Inv4Pi * (1.0f - g_ * g_) / (denom * std::sqrt(denom));
  }

  float g_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::HGPhase, PhaseFunction, "hg", "Henyey-Greenstein phase function")
