// Microfacet distributions (scattering/microfacet.h): normalisation of D and of
// the visible-normal density by numerical quadrature, chi-square tests of
// both sampling strategies, Mitsuba's parameters, and finite values at the
// extremes (alpha -> 0, grazing directions).
#include <gtest/gtest.h>

#include <femto/core/properties.h>
#include <femto/scattering/microfacet.h>

#include "chi2.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr float OneMinusEpsilonForTests = 0x1.fffffep-1f;  // the largest u a sampler gives

struct Config {
  MicrofacetType type;
  float alphaU, alphaV;
};

std::string describe(const Config& c) {
  return str(microfacetTypeName(c.type), " alpha=(", c.alphaU, ", ", c.alphaV, ")");
}

const Config Configs[] = {
    {MicrofacetType::Beckmann, 0.3f, 0.3f},
    {MicrofacetType::Beckmann, 0.15f, 0.6f},
    {MicrofacetType::GGX, 0.3f, 0.3f},
    {MicrofacetType::GGX, 0.6f, 0.15f},
};

Vec3f direction(float thetaDeg, float phiDeg) {
  float t = degToRad(thetaDeg), p = degToRad(phiDeg);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// Incident directions of the visible-normal tests: normal, oblique, grazing.
const Vec3f Incident[] = {direction(0, 0), direction(50, 30), direction(85, 200)};

// Chi-square tests in this file, for the Sidak correction.
constexpr int ChiSquareTests = 4 * 3 + 4;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

/// Integral of g(m) over the upper hemisphere by the midpoint rule in
/// (theta, phi), in double precision. Fine in theta: D of alpha = 0.1 is
/// about 0.1 rad wide.
double integrateHemisphere(const std::function<double(const Vec3f&)>& g, int nTheta = 3000, int nPhi = 256) {
  double sum = 0.0, dt = 0.5 * Pi / nTheta, dp = 2.0 * Pi / nPhi;
  for (int i = 0; i < nTheta; ++i) {
    double theta = (i + 0.5) * dt, st = std::sin(theta), ct = std::cos(theta);
    for (int j = 0; j < nPhi; ++j) {
      double phi = (j + 0.5) * dp;
      Vec3f m(float(st * std::cos(phi)), float(st * std::sin(phi)), float(ct));
      sum += g(m) * st;
    }
  }
  return sum * dt * dp;
}

/// (theta, phi) grid over the upper hemisphere only (microfacet normals).
GridDomain<Vec3f> hemisphereDomain(int nTheta, int nPhi) {
  GridDomain<Vec3f> d = sphericalDomain(nTheta, nPhi);
  d.x1 = 0.5 * Pi;
  return d;
}

}  // namespace

TEST(Microfacet, ProjectedAreaOfDIsOne) {
  // integral D(m) cos(theta_m) dm = 1 (Walter et al. 2007, eq. 4).
  std::vector<Config> configs(std::begin(Configs), std::end(Configs));
  configs.push_back({MicrofacetType::Beckmann, 0.1f, 0.1f});
  configs.push_back({MicrofacetType::GGX, 0.1f, 0.1f});
  configs.push_back({MicrofacetType::GGX, 1.0f, 1.0f});
  for (const Config& c : configs) {
    SCOPED_TRACE(describe(c));
    MicrofacetDistribution dist(c.type, c.alphaU, c.alphaV);
    double integral = integrateHemisphere([&](const Vec3f& m) { return double(dist.D(m)) * m.z; });
    EXPECT_NEAR(integral, 1.0, 2e-3);
  }
}

TEST(Microfacet, VisibleNormalDensityIsNormalised) {
  // integral G1(wi, m) max(0, wi.m) D(m) dm = cos(theta_i) (Heitz 2014, eq.
  // 17): holds only if Lambda is the exact Smith Lambda of D.
  for (const Config& c : Configs)
    for (const Vec3f& wi : Incident) {
      SCOPED_TRACE(str(describe(c), " wi=", wi));
      MicrofacetDistribution dist(c.type, c.alphaU, c.alphaV);
      double integral = integrateHemisphere([&](const Vec3f& m) { return double(dist.pdf(wi, m)); });
      EXPECT_NEAR(integral, 1.0, 2e-3);
    }
}

TEST(Microfacet, LambdaMatchesGGXClosedFormAndVanishesAtNormalIncidence) {
  // GGX: Lambda = (-1 + sqrt(1 + alpha^2 tan^2)) / 2 (Heitz 2014, eq. 86).
  MicrofacetDistribution ggx(MicrofacetType::GGX, 0.4f);
  Vec3f w = direction(60, 0);
  double a2t2 = 0.16 * 3.0;  // tan^2(60 deg) = 3
  EXPECT_NEAR(ggx.lambda(w), 0.5 * (std::sqrt(1.0 + a2t2) - 1.0), 1e-6);
  for (MicrofacetType type : {MicrofacetType::Beckmann, MicrofacetType::GGX}) {
    MicrofacetDistribution dist(type, 0.5f);
    EXPECT_EQ(dist.lambda({0, 0, 1}), 0.0f);
    EXPECT_EQ(dist.G1({0, 0, 1}, {0, 0, 1}), 1.0f);
    EXPECT_EQ(dist.G1({0.6f, 0, 0.8f}, {-0.8f, 0, 0.6f}), 0.0f) << "back-facing microfacet";
  }
}

namespace {

/// Chi-square tests of visible-normal sampling for the configurations of one
/// distribution. The reference density is written out here, not taken from
/// pdf(). Each test draws its own random numbers (seed), so the tests are
/// independent, as the Sidak correction assumes.
void expectVisibleSamplingMatches(MicrofacetType type, uint64_t seed) {
  for (const Config& c : Configs)
    for (const Vec3f& wi : Incident) {
      if (c.type != type) continue;
      SCOPED_TRACE(str(describe(c), " wi=", wi));
      MicrofacetDistribution dist(c.type, c.alphaU, c.alphaV, true);
      std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) { return dist.sample(wi, u); };
      std::function<double(const Vec3f&)> density = [&](const Vec3f& m) {
        return double(dist.G1(wi, m)) * std::max(0.0f, dot(wi, m)) * dist.D(m) / wi.z;
      };
      ChiSquareResult r = testSampler<Vec3f>(hemisphereDomain(32, 64), sample, density, 150000, 8, ++seed);
      EXPECT_GT(r.pValue, Significance) << r.message;
    }
}

}  // namespace

TEST(Microfacet, BeckmannVisibleNormalSamplingMatchesTheVisibleNormalDensity) {
  expectVisibleSamplingMatches(MicrofacetType::Beckmann, 100);
}

TEST(Microfacet, GGXVisibleNormalSamplingMatchesTheVisibleNormalDensity) {
  expectVisibleSamplingMatches(MicrofacetType::GGX, 150);
}

TEST(Microfacet, NormalSamplingMatchesDCosTheta) {
  uint64_t seed = 200;
  for (const Config& c : Configs) {
    SCOPED_TRACE(describe(c));
    MicrofacetDistribution dist(c.type, c.alphaU, c.alphaV, false);
    Vec3f wi = direction(40, 10);
    std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) { return dist.sample(wi, u); };
    std::function<double(const Vec3f&)> density = [&](const Vec3f& m) { return double(dist.D(m)) * m.z; };
    ChiSquareResult r = testSampler<Vec3f>(hemisphereDomain(32, 64), sample, density, 150000, 8, ++seed);
    EXPECT_GT(r.pValue, Significance) << r.message;
    EXPECT_NEAR(dist.pdf(wi, direction(20, 70)), dist.D(direction(20, 70)) * std::cos(degToRad(20)), 1e-5);
  }
}

TEST(Microfacet, IncidenceFromBelowIsMirrored) {
  MicrofacetDistribution dist(MicrofacetType::GGX, 0.3f, 0.5f);
  Vec3f wi = direction(30, 40), m = direction(10, 100);
  EXPECT_FLOAT_EQ(dist.pdf(-wi, m), dist.pdf(wi, m));
  Vec3f a = dist.sample(-wi, {0.3f, 0.7f}), b = dist.sample(wi, {0.3f, 0.7f});
  EXPECT_EQ(a, b);
}

TEST(Microfacet, ValuesStayFiniteAtTinyRoughnessAndGrazingAngles) {
  PCG32 rng(3, 1);
  for (MicrofacetType type : {MicrofacetType::Beckmann, MicrofacetType::GGX})
    for (bool visible : {true, false})
      for (float alpha : {1e-3f, 1e-5f, 2.0f})
        for (float cosTheta : {1.0f, 1e-2f, 1e-4f, 0.0f, -1e-4f}) {
          SCOPED_TRACE(str(microfacetTypeName(type), " alpha=", alpha, " cos=", cosTheta, " visible=", visible));
          MicrofacetDistribution dist(type, alpha, alpha * 0.5f, visible);
          Vec3f wi(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
          for (int k = 0; k < 200; ++k) {
            Point2f u(rng.nextFloat(), rng.nextFloat());
            if (k == 0) u = Point2f(0.0f, 0.0f);
            if (k == 1) u = Point2f(OneMinusEpsilonForTests, OneMinusEpsilonForTests);
            Vec3f m = dist.sample(wi, u);
            ASSERT_TRUE(isFinite(m)) << "u=" << u;
            ASSERT_NEAR(length(m), 1.0f, 1e-4f);
            ASSERT_GE(m.z, 0.0f);
            float pdf = dist.pdf(wi, m), D = dist.D(m), G = dist.G(wi, m, m);
            ASSERT_TRUE(std::isfinite(pdf) && pdf >= 0.0f) << pdf;
            ASSERT_TRUE(std::isfinite(D) && D >= 0.0f) << D;
            ASSERT_TRUE(std::isfinite(G) && G >= 0.0f && G <= 1.0f) << G;
          }
        }
}

TEST(Microfacet, TinyRoughnessIsClampedLikeMitsuba) {
  MicrofacetDistribution dist(MicrofacetType::Beckmann, 0.0f);
  EXPECT_EQ(dist.alphaU(), 1e-4f);
  EXPECT_TRUE(std::isfinite(dist.D({0, 0, 1})));
}

TEST(Microfacet, ReadsMitsubaParameters) {
  Properties defaults("roughconductor");
  MicrofacetDistribution d = MicrofacetDistribution::fromProperties(defaults);
  EXPECT_EQ(d.type(), MicrofacetType::Beckmann);
  EXPECT_EQ(d.alphaU(), 0.1f);
  EXPECT_EQ(d.alphaV(), 0.1f);
  EXPECT_TRUE(d.sampleVisible());

  Properties aniso("roughconductor");
  aniso.setString("distribution", "ggx");
  aniso.setFloat("alpha_u", 0.2);
  aniso.setFloat("alpha_v", 0.4);
  aniso.setBool("sample_visible", false);
  d = MicrofacetDistribution::fromProperties(aniso);
  EXPECT_EQ(d.type(), MicrofacetType::GGX);
  EXPECT_EQ(d.alphaU(), 0.2f);
  EXPECT_EQ(d.alphaV(), 0.4f);
  EXPECT_FALSE(d.sampleVisible());
  EXPECT_TRUE(aniso.unqueried().empty());

  // Isotropic-only plugins (roughplastic) do not read alpha_u: the loader then reports it as unused.
  Properties isoOnly("roughplastic");
  isoOnly.setFloat("alpha_u", 0.2);
  EXPECT_EQ(MicrofacetDistribution::fromProperties(isoOnly, false).alphaU(), 0.1f);
  EXPECT_EQ(isoOnly.unqueried(), std::vector<std::string>{"alpha_u"});
}

TEST(Microfacet, BadParametersNameTheParameter) {
  auto fileLine = [](int line) { return SourceLocation{"scene.xml", line}; };
  Properties unknown("roughconductor");
  unknown.setString("distribution", "phong", fileLine(7));
  std::string message = errorMessageOf([&] { MicrofacetDistribution::fromProperties(unknown); });
  EXPECT_NE(message.find("scene.xml:7"), std::string::npos) << message;
  EXPECT_NE(message.find("\"phong\""), std::string::npos) << message;

  Properties both("roughconductor");
  both.setFloat("alpha", 0.1, fileLine(3));
  both.setFloat("alpha_u", 0.1, fileLine(4));
  both.setFloat("alpha_v", 0.1, fileLine(5));
  message = errorMessageOf([&] { MicrofacetDistribution::fromProperties(both); });
  EXPECT_NE(message.find("scene.xml:3"), std::string::npos) << message;

  Properties half("roughconductor");
  half.setFloat("alpha_u", 0.1, fileLine(4));
  message = errorMessageOf([&] { MicrofacetDistribution::fromProperties(half); });
  EXPECT_NE(message.find("alpha_v"), std::string::npos) << message;

  Properties negative("roughconductor");
  negative.setFloat("alpha", -0.5, fileLine(9));
  message = errorMessageOf([&] { MicrofacetDistribution::fromProperties(negative); });
  EXPECT_NE(message.find("scene.xml:9"), std::string::npos) << message;
  EXPECT_NE(message.find("-0.5"), std::string::npos) << message;
}
