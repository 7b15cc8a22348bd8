// phong: the modified Phong reflectance model (Mitsuba 0.6's `phong`, after
// Lafortune & Willems 1994, "Using the Modified Phong Reflectance Model for
// Physically Based Rendering", eqs. 6-7): a Lambertian term and a glossy
// lobe around the mirror direction R of wi,
//
//   f(wi, wo) = kd / pi + ks (n + 2) / (2 pi) max(0, R . wo)^n,
//
// The (n + 2) / (2 pi) normalisation makes the lobe's albedo exactly ks at
// normal incidence and less elsewhere (part of the lobe falls below the
// horizon), so kd + ks <= 1 per channel conserves energy. As in Mitsuba 0.6,
// when max over channels of (kd + ks) exceeds 1 both are scaled by
// 0.99 / max, with a warning (`ensureEnergyConservation`, true by default;
// false keeps them). Mitsuba checks the maximum of a texture; femto's
// textures expose their mean, which is exact for constant values and a
// lower bound on the maximum of a bitmap. R . wo = wi . R(wo), so the model
// is reciprocal. One-sided.
//
// Sampling picks the lobe with probability s = lum(ks) / (lum(kd) + lum(ks))
// (mean values, Mitsuba's weight): cos^n-distributed around R (pdf
// (n + 1) / (2 pi) cos^n; directions below the horizon fail) or the
// cosine-weighted hemisphere.
//
// | name                       | type             | default | meaning                                | unit |
// |----------------------------|------------------|---------|----------------------------------------|------|
// | diffuse_reflectance        | rgb or texture   | 0.5     | kd, weight of the Lambertian term      | -    |
// | specular_reflectance       | rgb or texture   | 0.2     | ks, weight of the glossy lobe          | -    |
// | exponent                   | float or texture | 30      | n, the Phong exponent (mean of rgb)    | -    |
// | ensure_energy_conservation | boolean          | true    | scale kd and ks when they sum above 1  | -    |
#include <cmath>

#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/bsdf.h>
#include <femto/render/texture.h>

namespace femto {
namespace {

/// Mirror direction of w about the normal (local frame).
Vec3f reflectLocal(const Vec3f& w) { return {-w.x, -w.y, w.z}; }

/// A texture scaled by a constant (Mitsuba 0.6's energy fix).
class ScaledTexture final : public Texture {
 public:
  ScaledTexture(std::shared_ptr<Texture> nested, float scale) : nested_(std::move(nested)), scale_(scale) {}
  Color3f eval(const SurfaceInteraction& si) const override { return nested_->eval(si) * scale_; }
  Color3f mean() const override { return nested_->mean() * scale_; }
  Point2i resolution() const override { return nested_->resolution(); }
  std::string toString() const override { return str(nested_->toString(), " * ", scale_); }

 private:
  std::shared_ptr<Texture> nested_;
  float scale_;
};

}  // namespace

class PhongBSDF final : public BSDF {
 public:
  explicit PhongBSDF(const Properties& props)
      : diffuse_(textureOrColor(props, "diffuse_reflectance", Color3f(0.5f))),
        specular_(textureOrColor(props, "specular_reflectance", Color3f(0.2f))),
        exponent_(textureOrColor(props, "exponent", Color3f(30.0f))) {
    const Color3f kd = diffuse_->mean(), ks = specular_->mean();
    for (int c = 0; c < 3; ++c) {
      if (!(kd[c] >= 0.0f)) props.raise("diffuse_reflectance", str("must not be negative, got ", kd));
      if (!(ks[c] >= 0.0f)) props.raise("specular_reflectance", str("must not be negative, got ", ks));
    }
    if (!(exponent_->mean().average() >= 0.0f))
      props.raise("exponent", str("must not be negative, got ", exponent_->mean().average()));
    const float sumMax = std::max({kd.r + ks.r, kd.g + ks.g, kd.b + ks.b});
    if (props.getBool("ensure_energy_conservation", true) && sumMax > 1.0f) {
      const float scale = 0.99f / sumMax;
      const SourceLocation& where = props.location();
      logWarn(where.known() ? where.toString() + ": " : std::string(), "phong: diffuse_reflectance + ",
              "specular_reflectance reach ", sumMax, " > 1 and are scaled by ", scale,
              " (ensure_energy_conservation=false keeps them)");
      diffuse_ = std::make_shared<ScaledTexture>(diffuse_, scale);
      specular_ = std::make_shared<ScaledTexture>(specular_, scale);
    }
    const float d = diffuse_->mean().luminance(), s = specular_->mean().luminance();
    specularSamplingWeight_ = d + s > 0.0f ? s / (d + s) : 0.5f;
  }

  uint32_t flags() const override { return BSDFFlags::DiffuseReflection | BSDFFlags::GlossyReflection; }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    bs = BSDFSample();
    if (Frame::cosTheta(si.wi) <= 0.0f) return Color3f(0.0f);
    if (u1 < specularSamplingWeight_) {
      // cos^n around R: cos alpha = u^(1/(n+1)), phi uniform.
      const float n = exponent(si);
      const float cosAlpha = std::pow(u2.y, 1.0f / (n + 1.0f));
      const float sinAlpha = std::sqrt(std::max(0.0f, 1.0f - cosAlpha * cosAlpha));
      const float phi = 2.0f * Pi * u2.x;
      const Frame lobe(reflectLocal(si.wi));
      bs.wo = lobe.toWorld(Vec3f(sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha));
      bs.sampledFlags = BSDFFlags::GlossyReflection;
    } else {
      bs.wo = warp::squareToCosineHemisphere(u2);
      bs.sampledFlags = BSDFFlags::DiffuseReflection;
    }
    bs.pdf = pdf(si, bs.wo, mode);
    if (!(bs.pdf > 0.0f)) {
      bs.pdf = 0.0f;
      return Color3f(0.0f);
    }
    return eval(si, bs.wo, mode) / bs.pdf;
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    const float cosThetaI = Frame::cosTheta(si.wi), cosThetaO = Frame::cosTheta(wo);
    if (cosThetaI <= 0.0f || cosThetaO <= 0.0f) return Color3f(0.0f);
    Color3f f = diffuse_->eval(si) * InvPi;
    const float cosAlpha = dot(reflectLocal(si.wi), wo);
    if (cosAlpha > 0.0f) {
      const float n = exponent(si);
      f += specular_->eval(si) * ((n + 2.0f) * Inv2Pi * std::pow(cosAlpha, n));
    }
    return f * cosThetaO;
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode) const override {
    if (Frame::cosTheta(si.wi) <= 0.0f || Frame::cosTheta(wo) <= 0.0f) return 0.0f;
    const float cosAlpha = dot(reflectLocal(si.wi), wo);
    float lobe = 0.0f;
    if (cosAlpha > 0.0f) {
      const float n = exponent(si);
      lobe = (n + 1.0f) * Inv2Pi * std::pow(cosAlpha, n);
    }
    return specularSamplingWeight_ * lobe + (1.0f - specularSamplingWeight_) * warp::squareToCosineHemispherePdf(wo);
  }

  std::string toString() const override {
    return str("PhongBSDF[diffuse_reflectance=", diffuse_->toString(), ", specular_reflectance=", specular_->toString(),
               ", exponent=", exponent_->toString(), "]");
  }

 private:
  float exponent(const SurfaceInteraction& si) const { return std::max(0.0f, exponent_->eval(si).average()); }

  std::shared_ptr<Texture> diffuse_, specular_, exponent_;
  float specularSamplingWeight_ = 0.5f;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::PhongBSDF, BSDF, "phong", "Modified Phong reflectance (Lafortune & Willems 1994)")
