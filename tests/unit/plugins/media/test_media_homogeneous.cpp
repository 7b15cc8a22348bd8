// The homogeneous medium against closed forms: transmittance exp(-sigma_t d),
// the free-flight distribution (chi-square), unbiased chromatic weights,
// free flights conditioned to scatter before a reach (time gating), and
// the parameter spellings of Mitsuba 0.6 and 3.
#include <gtest/gtest.h>

#include <cmath>

#include "chi2.h"
#include "media_test_util.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

const Medium& mediumOf(const Scene& scene) { return *scene.sensor().medium(); }

}  // namespace

TEST(MediaHomogeneous, TransmittanceIsBeerLambert) {
  auto scene = sceneWithMedium(R"(<medium id="m" type="homogeneous">
      <rgb name="sigma_t" value="0.5, 1, 2"/><float name="scale" value="2"/></medium>)");
  const Medium& medium = mediumOf(*scene);
  auto sampler = seededSampler();
  Ray ray(Point3f(0.3f, -1.0f, 2.0f), normalize(Vec3f(1, 2, -0.5f)));
  for (float d : {0.0f, 0.1f, 0.7f, 3.0f}) {
    Color3f tr = medium.transmittance(ray, d, *sampler);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(tr[c], std::exp(-2.0 * Color3f(0.5f, 1, 2)[c] * d), 1e-6) << d;
  }
  EXPECT_EQ(medium.transmittance(ray, Infinity, *sampler), Color3f(0.0f));
  EXPECT_TRUE(medium.isHomogeneous());
  EXPECT_EQ(medium.majorant(), Color3f(1, 2, 4));
}

TEST(MediaHomogeneous, FreeFlightDistanceFollowsTheExponential) {
  // Grey medium: t has density sigma_t exp(-sigma_t t) on [0, tMax) and the
  // rest of the mass, exp(-sigma_t tMax), crosses the segment.
  const float sigmaT = 1.5f, tMax = 2.0f;
  auto scene = sceneWithMedium(R"(<medium id="m" type="homogeneous"><float name="sigma_t" value="1.5"/>
      <float name="albedo" value="0.6"/></medium>)");
  const Medium& medium = mediumOf(*scene);
  auto sampler = seededSampler(3);
  const int bins = 40, n = 200000;
  std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);
  Ray ray(Point3f(0, 0, 0), Vec3f(0, 0, 1));
  Mean meanT;
  for (int i = 0; i < n; ++i) {
    MediumSample ms = medium.sampleDistance(ray, tMax, *sampler);
    if (ms.scattered) {
      ASSERT_LT(ms.t, tMax);
      EXPECT_NEAR(ms.p.z, ms.t, 1e-5f);
      EXPECT_NEAR(ms.weight.r, 0.6f, 1e-5f);  // sigma_s T / pdf = albedo for a grey medium
      observed[std::min(int(ms.t / tMax * bins), bins - 1)] += 1.0;
    } else {
      EXPECT_EQ(ms.t, tMax);
      EXPECT_NEAR(ms.weight.r, 1.0f, 1e-5f);
      observed[bins] += 1.0;
    }
    meanT.add(std::min(ms.t, tMax));
  }
  for (int b = 0; b < bins; ++b) {
    double t0 = tMax * b / bins, t1 = tMax * (b + 1) / bins;
    expected[b] = n * (std::exp(-sigmaT * t0) - std::exp(-sigmaT * t1));
  }
  expected[bins] = n * std::exp(-sigmaT * tMax);
  ChiSquareResult r = chiSquareTest(observed, expected);
  EXPECT_GT(r.pValue, 1e-3) << r.message;
  // E[min(t, tMax)] = (1 - exp(-sigma_t tMax)) / sigma_t.
  expectWithinErrorBars(meanT, (1.0 - std::exp(-sigmaT * tMax)) / sigmaT, 1e-6, "mean free flight");
}

TEST(MediaHomogeneous, ChromaticWeightsAreUnbiased) {
  // One-sample MIS over channels: E[weight | crossed] P = T(tMax) and
  // E[weight at scattering] = sigma_s (1 - exp(-sigma_t tMax)) / sigma_t, per channel.
  const Color3f sigmaS(0.2f, 0.9f, 0.0f), sigmaA(0.3f, 0.1f, 2.0f);
  const float tMax = 1.3f;
  auto scene = sceneWithMedium(R"(<medium id="m" type="homogeneous"><rgb name="sigma_s" value="0.2, 0.9, 0"/>
      <rgb name="sigma_a" value="0.3, 0.1, 2"/></medium>)");
  const Medium& medium = mediumOf(*scene);
  auto sampler = seededSampler(5);
  Mean crossed[3], scattered[3];
  Ray ray(Point3f(1, 2, 3), Vec3f(1, 0, 0));
  for (int i = 0; i < 200000; ++i) {
    MediumSample ms = medium.sampleDistance(ray, tMax, *sampler);
    for (int c = 0; c < 3; ++c) {
      crossed[c].add(ms.scattered ? 0.0 : ms.weight[c]);
      scattered[c].add(ms.scattered ? ms.weight[c] : 0.0);
    }
  }
  for (int c = 0; c < 3; ++c) {
    double sigmaT = sigmaS[c] + sigmaA[c];
    expectWithinErrorBars(crossed[c], std::exp(-sigmaT * tMax), 1e-6, str("transmittance, channel ", c));
    expectWithinErrorBars(scattered[c], sigmaS[c] * (1.0 - std::exp(-sigmaT * tMax)) / sigmaT, 1e-6,
                          str("scattering, channel ", c));
  }
}

TEST(MediaHomogeneous, InfiniteSegmentAlwaysScatters) {
  auto scene = sceneWithMedium(R"(<medium id="m" type="homogeneous"><float name="sigma_t" value="0.01"/></medium>)");
  auto sampler = seededSampler(9);
  for (int i = 0; i < 100; ++i)
    EXPECT_TRUE(mediumOf(*scene).sampleDistance(Ray(Point3f(0.0f), Vec3f(0, 1, 0)), Infinity, *sampler).scattered);
}

TEST(MediaHomogeneous, Mitsuba06SpellingIsUpgraded) {
  // sigmaS/sigmaA (0.6) become sigma_s/sigma_a; the medium reports sigma_t = sigma_s + sigma_a, scaled.
  auto scene = sceneWithMedium(R"(<medium id="m" type="homogeneous"><rgb name="sigmaS" value="1, 2, 3"/>
      <rgb name="sigmaA" value="0.5, 0.5, 0.5"/><float name="scale" value="0.1"/><float name="eta" value="1.33"/>
      </medium>)", "0.6.0");
  const Medium& medium = mediumOf(*scene);
  Color3f m = medium.majorant();
  EXPECT_NEAR(m.r, 0.15f, 1e-6f);
  EXPECT_NEAR(m.g, 0.25f, 1e-6f);
  EXPECT_NEAR(m.b, 0.35f, 1e-6f);
  EXPECT_FLOAT_EQ(medium.eta(), 1.33f);
  // 0.6's sigmaT/albedo too.
  auto other = sceneWithMedium(R"(<medium id="m" type="homogeneous"><float name="sigmaT" value="4"/>
      <float name="albedo" value="0.5"/></medium>)", "0.6.0");
  EXPECT_EQ(mediumOf(*other).majorant(), Color3f(4.0f));
}

TEST(MediaHomogeneous, BadParametersAreErrors) {
  auto message = [](const std::string& body) {
    return errorMessageOf([&] { sceneWithMedium(str(R"(<medium id="m" type="homogeneous">)", body, "</medium>")); });
  };
  EXPECT_NE(message(R"(<float name="sigma_s" value="1"/><float name="albedo" value="0.5"/>)").find("not both"),
            std::string::npos);
  EXPECT_NE(message(R"(<float name="sigma_t" value="-1"/>)").find("sigma_t"), std::string::npos);
  EXPECT_NE(message(R"(<float name="albedo" value="1.5"/>)").find("albedo"), std::string::npos);
  EXPECT_NE(message(R"(<float name="eta" value="0.5"/>)").find("eta"), std::string::npos);
  EXPECT_NE(message(R"(<float name="scale" value="-2"/>)").find("scale"), std::string::npos);
  // The loader names the line of the offending parameter.
  std::string m = message("\n<float name=\"sigma_a\" value=\"-1\"/>");
  EXPECT_NE(m.find(":2"), std::string::npos) << m;
}

TEST(MediaHomogeneous, PhaseFunctionIsNestedOrIsotropic) {
  auto scene = sceneWithMedium(R"(<medium id="m" type="homogeneous"><phase type="hg"><float name="g" value="0.3"/>
      </phase></medium>)");
  EXPECT_NE(mediumOf(*scene).phase().toString().find("g=0.3"), std::string::npos);
  auto plain = sceneWithMedium(R"(<medium id="m" type="homogeneous"/>)");
  EXPECT_NE(mediumOf(*plain).phase().toString().find("Isotropic"), std::string::npos);
}

TEST(MediaHomogeneous, FreeFlightsBeforeAReachEstimateTheTruncatedIntegral) {
  // Time gating's truncated free flight (Medium::sampleDistanceBefore) in a
  // chromatic homogeneous medium: E[weight f(t)] of free flights
  // conditioned on t < reach must be the integral over [0, reach) of
  // sigma_s T(t) f(t) per channel, for f = 1 and f = t; the samples stay
  // inside, and the density is the medium's over P(t < reach).
  auto scene = sceneWithMedium(R"(<medium id="m" type="homogeneous">
      <rgb name="sigma_t" value="0.3, 1.2, 2.5"/><rgb name="albedo" value="0.9, 0.6, 0.8"/></medium>)");
  const Medium& medium = *scene->sensor().medium();
  const Color3f sigmaT(0.3f, 1.2f, 2.5f), sigmaS = sigmaT * Color3f(0.9f, 0.6f, 0.8f);
  auto sampler = seededSampler(5);
  Ray ray(Point3f(0.0f), Vec3f(0, 0, 1));
  for (float reach : {0.15f, 0.9f, 3.0f}) {
    const int n = 200000;
    Mean zeroth[3], first[3];
    float p = medium.scatterProbabilityBefore(reach);
    for (int i = 0; i < n; ++i) {
      MediumSample ms = medium.sampleDistanceBefore(ray, reach, *sampler);
      ASSERT_TRUE(ms.scattered);
      ASSERT_GE(ms.t, 0.0f);
      ASSERT_LT(ms.t, reach);
      for (int c = 0; c < 3; ++c) {
        zeroth[c].add(ms.weight[c]);
        first[c].add(ms.weight[c] * ms.t);
      }
    }
    double expectedP = 0.0;
    for (int c = 0; c < 3; ++c) expectedP += (1.0 - std::exp(-double(sigmaT[c]) * reach)) / 3.0;
    EXPECT_NEAR(p, expectedP, 1e-6);
    for (int c = 0; c < 3; ++c) {
      double s = sigmaT[c], a = sigmaS[c] / s;
      double e0 = a * (1.0 - std::exp(-s * reach));
      double e1 = a * ((1.0 - std::exp(-s * reach)) / s - reach * std::exp(-s * reach));
      EXPECT_NEAR(zeroth[c].mean(), e0, 4.0 * zeroth[c].standardError() + 1e-6)
          << "reach " << reach << " channel " << c;
      EXPECT_NEAR(first[c].mean(), e1, 4.0 * first[c].standardError() + 1e-6) << "reach " << reach << " channel " << c;
    }
  }
  MediumSample none = medium.sampleDistanceBefore(ray, 0.0f, *sampler);
  EXPECT_TRUE(none.weight.isBlack()) << "nothing scatters before 0";
}
