// Phase functions: chi-square tests of sampling against eval, normalisation
// over the sphere, sample weights, and the scattering delay distribution.
#include <gtest/gtest.h>

#include <femto/math/frame.h>
#include <femto/render/phase.h>

#include "chi2.h"
#include "media_test_util.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::shared_ptr<PhaseFunction> makePhase(const std::string& type, std::initializer_list<std::pair<const char*, float>> params) {
  Properties props(type);
  for (const auto& [name, value] : params) props.setFloat(name, value);
  return makePlugin<PhaseFunction>(ObjectKind::PhaseFunction, props);
}

/// Integral of eval(wi, .) over the sphere by the midpoint rule in (theta, phi)
/// around the propagation direction -wi (where HG peaks), in double precision.
double integrateOverSphere(const PhaseFunction& phase, const Vec3f& wi) {
  const int nTheta = 2000, nPhi = 64;
  Frame frame(-wi);
  double sum = 0.0;
  for (int i = 0; i < nTheta; ++i) {
    double theta = Pi * (i + 0.5) / nTheta;
    for (int j = 0; j < nPhi; ++j) {
      double phi = 2.0 * Pi * (j + 0.5) / nPhi;
      Vec3f wo = frame.toWorld(Vec3f(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                                     float(std::cos(theta))));
      sum += phase.eval(wi, wo) * std::sin(theta);
    }
  }
  return sum * (Pi / nTheta) * (2.0 * Pi / nPhi);
}

}  // namespace

TEST(MediaPhase, HenyeyGreensteinSamplingMatchesEval) {
  const Vec3f wi = normalize(Vec3f(0.3f, -0.5f, 0.8f));
  for (float g : {-0.7f, -0.2f, 0.0f, 0.4f, 0.85f}) {
    SCOPED_TRACE(str("g = ", g));
    auto phase = makePhase("hg", {{"g", g}});
    auto result = testSampler<Vec3f>(
        sphericalDomain(32, 16),
        [&](const Point2f& u) {
          Vec3f wo;
          float pdf = 0.0f;
          float weight = phase->sample(wi, u, wo, pdf);
          EXPECT_NEAR(weight, 1.0f, 1e-5f);
          EXPECT_NEAR(pdf, phase->pdf(wi, wo), 1e-4f * pdf);
          return wo;
        },
        [&](const Vec3f& wo) { return double(phase->pdf(wi, wo)); }, 200000, 8);
    EXPECT_GT(result.pValue, sidakSignificance(0.01, 5)) << result.message;
  }
}

TEST(MediaPhase, HenyeyGreensteinIsNormalisedAndForwardForPositiveG) {
  const Vec3f wi(0, 0, 1);
  for (float g : {-0.6f, 0.0f, 0.5f, 0.9f}) {
    auto phase = makePhase("hg", {{"g", g}});
    EXPECT_NEAR(integrateOverSphere(*phase, wi), 1.0, 2e-3) << "g = " << g;
    // The mean cosine of the scattering angle (between -wi and wo) is g.
    Mean cosine;
    auto sampler = seededSampler(11);
    for (int i = 0; i < 50000; ++i) {
      Vec3f wo;
      float pdf;
      phase->sample(wi, sampler->next2D(), wo, pdf);
      cosine.add(-dot(wi, wo));
    }
    expectWithinErrorBars(cosine, g, 1e-6, str("mean cosine for g = ", g));
  }
}

TEST(MediaPhase, IsotropicIsUniform) {
  auto phase = makePhase("isotropic", {});
  const Vec3f wi(0, 1, 0);
  EXPECT_NEAR(integrateOverSphere(*phase, wi), 1.0, 1e-3);
  auto result = testSampler<Vec3f>(
      sphericalDomain(16, 16),
      [&](const Point2f& u) {
        Vec3f wo;
        float pdf;
        EXPECT_EQ(phase->sample(wi, u, wo, pdf), 1.0f);
        return wo;
      },
      [&](const Vec3f& wo) { return double(phase->pdf(wi, wo)); }, 100000);
  EXPECT_GT(result.pValue, 0.01) << result.message;
}

TEST(MediaPhase, ScatteringDelayIsConstantPlusExponential) {
  EXPECT_FALSE(makePhase("isotropic", {})->hasDelay());
  EXPECT_EQ(makePhase("isotropic", {})->sampleDelay(0.7f), 0.0);
  auto constant = makePhase("isotropic", {{"delay", 0.25f}});
  EXPECT_TRUE(constant->hasDelay());
  EXPECT_DOUBLE_EQ(constant->sampleDelay(0.3f), 0.25);
  // delay + Exp(mean lifetime): mean delay + lifetime, P(extra > x) = exp(-x / lifetime).
  auto lifetime = makePhase("hg", {{"g", 0.2f}, {"delay", 0.1f}, {"lifetime", 0.5f}});
  auto sampler = seededSampler(13);
  Mean mean, tail;
  for (int i = 0; i < 100000; ++i) {
    double d = lifetime->sampleDelay(sampler->next1D());
    ASSERT_GE(d, 0.1 - 1e-7);
    mean.add(d);
    tail.add(d - 0.1 > 1.0 ? 1.0 : 0.0);
  }
  expectWithinErrorBars(mean, 0.6, 1e-6, "mean delay");
  expectWithinErrorBars(tail, std::exp(-2.0), 1e-6, "tail probability");
}

TEST(MediaPhase, BadParametersAreErrors) {
  EXPECT_NE(errorMessageOf([] { makePhase("hg", {{"g", 1.0f}}); }).find("\"g\""), std::string::npos);
  EXPECT_NE(errorMessageOf([] { makePhase("isotropic", {{"lifetime", -1.0f}}); }).find("lifetime"), std::string::npos);
}
