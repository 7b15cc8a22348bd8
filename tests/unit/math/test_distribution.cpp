// Piecewise-constant distributions (math/distribution.h): sampling checked
// against the claimed density with the chi-square test of chi2.h.
#include <gtest/gtest.h>

#include <numeric>

#include <femto/base/error.h>
#include <femto/math/distribution.h>

#include "chi2.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int ChiSquareTests = 2;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

}  // namespace

TEST(Distribution1D, ProbabilitiesAreNormalisedWeights) {
  Distribution1D d({1.0f, 3.0f, 0.0f, 4.0f});
  EXPECT_FLOAT_EQ(d.integral(), 2.0f);
  EXPECT_FLOAT_EQ(d.probability(0), 0.125f);
  EXPECT_FLOAT_EQ(d.probability(1), 0.375f);
  EXPECT_EQ(d.probability(2), 0.0f);
  EXPECT_FLOAT_EQ(d.probability(3), 0.5f);
  EXPECT_FLOAT_EQ(d.pdf(0.3f), 0.375f * 4.0f);
  EXPECT_EQ(d.pdf(0.6f), 0.0f);
  EXPECT_EQ(d.pdf(1.0f), 0.0f);
  EXPECT_EQ(d.pdf(-0.1f), 0.0f);
}

TEST(Distribution1D, DiscreteSamplingNeverPicksEmptyBinsAndRemapsU) {
  Distribution1D d({1.0f, 0.0f, 0.0f, 3.0f});
  // Bin 0 owns u in [0, 0.25), bin 3 owns [0.25, 1); u at the boundary and 1 - eps stay off empty bins.
  for (float u : {0.0f, 0.1f, 0.2499f, 0.25f, 0.5f, 0.99999994f}) {
    float p = 0.0f, remapped = -1.0f;
    size_t i = d.sampleDiscrete(u, &p, &remapped);
    EXPECT_TRUE(i == 0 || i == 3) << "u = " << u;
    EXPECT_FLOAT_EQ(p, d.probability(i));
    EXPECT_GE(remapped, 0.0f);
    EXPECT_LT(remapped, 1.0f);
  }
  float remapped = 0.0f;
  EXPECT_EQ(d.sampleDiscrete(0.625f, nullptr, &remapped), 3u);
  EXPECT_NEAR(remapped, 0.5f, 1e-6f);
}

TEST(Distribution1D, ContinuousSamplingMatchesItsPdf) {
  Distribution1D d({0.5f, 2.0f, 0.0f, 1.0f, 4.0f, 0.25f, 0.0f, 3.0f});
  std::function<Point2f(const Point2f&)> sample = [&](const Point2f& u) {
    float pdf = 0.0f;
    float x = d.sampleContinuous(u.x, &pdf);
    EXPECT_FLOAT_EQ(pdf, d.pdf(x));
    return Point2f(x, u.y);  // y: an independent uniform coordinate, density 1
  };
  std::function<double(const Point2f&)> pdf = [&](const Point2f& p) { return d.pdf(p.x); };
  ChiSquareResult r = testSampler<Point2f>(planarDomain(0, 1, 0, 1, 32, 2), sample, pdf, 200000);
  EXPECT_GT(r.pValue, Significance) << r.message;
}

TEST(Distribution1D, AllZeroWeightsSampleUniformlyWithZeroIntegral) {
  Distribution1D d({0.0f, 0.0f});
  EXPECT_EQ(d.integral(), 0.0f);
  EXPECT_FLOAT_EQ(d.pdf(0.7f), 1.0f);
  EXPECT_EQ(d.sampleDiscrete(0.7f), 1u);
}

TEST(Distribution1D, BadWeightsAreErrors) {
  EXPECT_THROW(Distribution1D(std::vector<float>{}), Error);
  EXPECT_THROW(Distribution1D({1.0f, -1.0f}), Error);
  EXPECT_THROW(Distribution1D({1.0f, std::numeric_limits<float>::quiet_NaN()}), Error);
  EXPECT_THROW(Distribution1D({1.0f, Infinity}), Error);
}

TEST(Distribution2D, SamplingMatchesItsPdf) {
  // 5 x 3 cells with an empty cell and an empty row.
  const int w = 5, h = 3;
  std::vector<float> weights = {1, 2, 0, 4, 1,  //
                                0, 0, 0, 0, 0,  //
                                3, 1, 1, 0.5f, 6};
  Distribution2D d(weights, w, h);
  EXPECT_FLOAT_EQ(d.integral(), std::accumulate(weights.begin(), weights.end(), 0.0f) / (w * h));
  std::function<Point2f(const Point2f&)> sample = [&](const Point2f& u) {
    float pdf = 0.0f;
    Point2f p = d.sample(u, &pdf);
    EXPECT_FLOAT_EQ(pdf, d.pdf(p));
    return p;
  };
  std::function<double(const Point2f&)> pdf = [&](const Point2f& p) { return d.pdf(p); };
  ChiSquareResult r = testSampler<Point2f>(planarDomain(0, 1, 0, 1, 20, 12), sample, pdf, 300000);
  EXPECT_GT(r.pValue, Significance) << r.message;
  // The density is the normalised weight of the cell.
  EXPECT_FLOAT_EQ(d.pdf({0.65f, 0.1f}), 4.0f / d.integral());
  EXPECT_EQ(d.pdf({0.5f, 0.5f}), 0.0f);
}

TEST(Distribution2D, UniformWeightsGiveTheUniformDensity) {
  Distribution2D d(std::vector<float>(12, 0.7f), 4, 3);
  PCG32 rng;
  for (int i = 0; i < 100; ++i) {
    float pdf = 0.0f;
    Point2f p = d.sample({rng.nextFloat(), rng.nextFloat()}, &pdf);
    EXPECT_NEAR(pdf, 1.0f, 1e-5f);
    EXPECT_NEAR(d.pdf(p), 1.0f, 1e-5f);
  }
}

TEST(Distribution2D, SizeMismatchIsAnError) {
  EXPECT_THROW(Distribution2D(std::vector<float>(5, 1.0f), 2, 3), Error);
  EXPECT_THROW(Distribution2D(std::vector<float>(), 0, 0), Error);
}
