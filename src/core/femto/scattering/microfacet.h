#pragma once
// Microfacet normal distributions for rough surfaces: Beckmann and GGX
// (Trowbridge-Reitz), isotropic or anisotropic, in the local shading frame
// (macro-normal = +z). Shared by roughconductor, roughdielectric and
// roughplastic.
//
// References:
// - B. Walter, S. Marschner, H. Li, K. Torrance, "Microfacet Models for
//   Refraction through Rough Surfaces", EGSR 2007 (D, G1, the BSDFs).
// - E. Heitz, "Understanding the Masking-Shadowing Function in
//   Microfacet-Based BRDFs", JCGT 3(2), 2014 (Smith Lambda, anisotropy via
//   the projected roughness, the visible-normal density D_wi).
// - E. Heitz, E. d'Eon, "Importance Sampling Microfacet-Based BSDFs using the
//   Distribution of Visible Normals", EGSR 2014 (visible slopes, Beckmann).
// - E. Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4),
//   2018 (GGX visible normals).
#include <string>

#include <femto/math/vector.h>

namespace femto {

class Properties;

enum class MicrofacetType { Beckmann, GGX };

/// Mitsuba's spelling of a distribution ("beckmann", "ggx").
const char* microfacetTypeName(MicrofacetType type);

class MicrofacetDistribution {
 public:
  /// Roughnesses are the RMS slopes (Beckmann) / width parameters (GGX) along
  /// the tangent (u) and bitangent (v). Values below 1e-4 are raised to 1e-4,
  /// as Mitsuba 3 does: below that D overflows single precision, and the
  /// surface is then a mirror for every practical purpose.
  MicrofacetDistribution(MicrofacetType type, float alphaU, float alphaV, bool sampleVisible = true);
  MicrofacetDistribution(MicrofacetType type, float alpha, bool sampleVisible = true)
      : MicrofacetDistribution(type, alpha, alpha, sampleVisible) {}

  /// Mitsuba's parameters: `distribution` ("beckmann" (default) or "ggx"),
  /// `alpha` (default 0.1) or, when `allowAnisotropic`, `alpha_u`/`alpha_v`
  /// (not together with `alpha`), and `sample_visible` (default true).
  /// Bad values are errors naming the parameter's file:line.
  static MicrofacetDistribution fromProperties(const Properties& props, bool allowAnisotropic = true);

  MicrofacetType type() const { return type_; }
  float alphaU() const { return alphaU_; }
  float alphaV() const { return alphaV_; }
  bool sampleVisible() const { return sampleVisible_; }
  bool isAnisotropic() const { return alphaU_ != alphaV_; }
  /// The same distribution with another sampling strategy.
  MicrofacetDistribution withSampleVisible(bool visible) const {
    return MicrofacetDistribution(type_, alphaU_, alphaV_, visible);
  }

  /// Microfacet normal density D(m) (per unit solid angle of m, projected:
  /// the integral of D(m) cos(theta_m) over the hemisphere is 1). Zero for
  /// m below the horizon. Walter et al. eqs. 25 (Beckmann) and 33 (GGX), in
  /// the anisotropic form written with the components of m.
  float D(const Vec3f& m) const;
  /// Smith's Lambda(w) for the exact Smith masking of the distribution
  /// (Heitz 2014, eqs. 72 and 86). For Beckmann this uses erfc, not Walter's
  /// rational approximation (eq. 27, G1 ~ (3.535a + 2.181a^2) / (1 + 2.276a
  /// + 2.577a^2) for a < 1.6): the visible-normal density is normalised by
  /// exactly 1 + Lambda, so only the exact form keeps sample() and pdf()
  /// consistent.
  float lambda(const Vec3f& w) const;
  /// Smith masking of direction w for microfacet m: 1 / (1 + Lambda(w)), and
  /// zero when w sees the back of m (Walter's chi+(w.m / w.n)).
  float G1(const Vec3f& w, const Vec3f& m) const;
  /// Separable Smith shadowing-masking G1(wi, m) G1(wo, m) (Walter eq. 23),
  /// as Mitsuba uses; valid for reflection and transmission.
  float G(const Vec3f& wi, const Vec3f& wo, const Vec3f& m) const;

  /// Sample a microfacet normal (m.z > 0). With visible sampling, m follows
  /// D_wi(m) = G1(wi, m) max(0, wi.m) D(m) / cos(theta_i) (Heitz 2014, eq.
  /// 38), else D(m) cos(theta_m). `wi` below the surface (a ray inside a
  /// dielectric) is mirrored into the upper hemisphere first, as in Mitsuba.
  Vec3f sample(const Vec3f& wi, const Point2f& u) const;
  /// Density of sample() choosing `m`, per unit solid angle of m.
  float pdf(const Vec3f& wi, const Vec3f& m) const;
  /// The factor D(m) G(wi, wo, m) |wi.m| / (|cos theta_i| pdf(wi, m)) of the
  /// Monte Carlo weight f |cos theta_o| / pdf(wo) of a direction wo reached
  /// through a sampled m, shared by reflection and refraction once the
  /// Fresnel factor, the choice between them and refraction's eta^2 are set
  /// aside (Walter et al. eqs. 38-41). Written in closed form: G1(wo, m) for
  /// visible sampling (Heitz & d'Eon 2014, sec. 3.2), G |wi.m| /
  /// (|cos theta_i| cos theta_m) otherwise. Zero when wi sees the back of m.
  float sampleWeight(const Vec3f& wi, const Vec3f& wo, const Vec3f& m) const;

  std::string toString() const;

 private:
  /// alpha_u^2 x^2 + alpha_v^2 y^2: the projected roughness of direction w
  /// squared, times sin^2(theta) (Heitz 2014, eq. 80).
  float projectedRoughness2(const Vec3f& w) const;
  Vec3f sampleVisibleGGX(const Vec3f& wi, const Point2f& u) const;
  Vec3f sampleVisibleBeckmann(const Vec3f& wi, const Point2f& u) const;
  Vec3f sampleAll(const Point2f& u) const;

  MicrofacetType type_;
  float alphaU_, alphaV_;
  bool sampleVisible_;
};

}  // namespace femto
