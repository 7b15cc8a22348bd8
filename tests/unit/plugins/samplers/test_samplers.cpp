// The stratified and low-discrepancy samplers: one sample per stratum in
// every dimension, determinism in (seed, pixel), every sampler's samples
// independent of how many numbers earlier samples used, uniformity over many pixels
// (chi-square) and a lower integration error than independent sampling on a
// smooth integrand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <femto/render/sampler.h>

#include "chi2.h"
#include "render_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::shared_ptr<Sampler> makeSampler(const std::string& name, int64_t sampleCount) {
  Properties props(name);
  props.setInt("sample_count", sampleCount);
  auto sampler = makePlugin<Sampler>(ObjectKind::Sampler, props);
  if (!sampler) throw Error(str("no sampler plugin \"", name, "\""));
  return sampler;
}

/// The values one pixel's samples take in each dimension, consumed as the
/// render loop and an integrator do: a 2D film position, a 1D value, 2D, 1D, 2D.
struct PixelSamples {
  std::vector<std::vector<Point2f>> dims2D;  // [dimension][sample]
  std::vector<std::vector<float>> dims1D;
};

PixelSamples drawPixel(Sampler& sampler, uint64_t seed, uint64_t pixel) {
  PixelSamples result;
  result.dims2D.resize(3);
  result.dims1D.resize(2);
  sampler.startPixel(seed, pixel);
  for (uint32_t s = 0; s < sampler.sampleCount(); ++s) {
    result.dims2D[0].push_back(sampler.next2D());
    result.dims1D[0].push_back(sampler.next1D());
    result.dims2D[1].push_back(sampler.next2D());
    result.dims1D[1].push_back(sampler.next1D());
    result.dims2D[2].push_back(sampler.next2D());
    sampler.advance();
  }
  return result;
}

/// Every cell of an nx x ny grid over [0,1)^2 holds exactly one point.
void expectOnePerCell(const std::vector<Point2f>& points, int nx, int ny) {
  std::vector<int> count(size_t(nx * ny), 0);
  for (const Point2f& p : points) {
    ASSERT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f) << p;
    ++count[size_t(int(p.y * ny) * nx + int(p.x * nx))];
  }
  for (int c : count) EXPECT_EQ(c, 1) << nx << " x " << ny << " grid";
}

void expectOnePerInterval(const std::vector<float>& values) {
  std::vector<Point2f> asPoints;
  for (float v : values) asPoints.push_back({v, 0.0f});
  expectOnePerCell(asPoints, int(values.size()), 1);
}

}  // namespace

TEST(StratifiedSampler, OneSamplePerStratumInEveryDimension) {
  auto sampler = makeSampler("stratified", 16)->clone();
  for (uint64_t pixel : {0u, 1u, 977u}) {
    PixelSamples px = drawPixel(*sampler, 3, pixel);
    for (const auto& dim : px.dims2D) expectOnePerCell(dim, 4, 4);
    for (const auto& dim : px.dims1D) expectOnePerInterval(dim);
  }
}

TEST(StratifiedSampler, RoundsUpToASquareAndCentresWithoutJitter) {
  EXPECT_EQ(makeSampler("stratified", 10)->sampleCount(), 16u);
  EXPECT_EQ(makeSampler("stratified", 9)->sampleCount(), 9u);
  Properties props("stratified");
  props.setInt("sample_count", 4);
  props.setBool("jitter", false);
  auto sampler = makePlugin<Sampler>(ObjectKind::Sampler, props)->clone();
  PixelSamples px = drawPixel(*sampler, 1, 2);
  for (const Point2f& p : px.dims2D[1]) {
    EXPECT_TRUE(p.x == 0.25f || p.x == 0.75f) << p;
    EXPECT_TRUE(p.y == 0.25f || p.y == 0.75f) << p;
  }
}

TEST(LowDiscrepancySampler, EveryElementaryIntervalHoldsOneSample) {
  // A (0,4,2)-net in base 2: one point in each of the 16 cells of every
  // 1x16, 2x8, 4x4, 8x2 and 16x1 partition, in every (padded) dimension.
  auto sampler = makeSampler("ldsampler", 16)->clone();
  for (uint64_t pixel : {0u, 5u, 4096u}) {
    PixelSamples px = drawPixel(*sampler, 9, pixel);
    for (const auto& dim : px.dims2D)
      for (int nx : {1, 2, 4, 8, 16}) expectOnePerCell(dim, nx, 16 / nx);
    for (const auto& dim : px.dims1D) expectOnePerInterval(dim);
  }
}

TEST(LowDiscrepancySampler, RoundsUpToAPowerOfTwo) {
  EXPECT_EQ(makeSampler("ldsampler", 5)->sampleCount(), 8u);
  EXPECT_EQ(makeSampler("ldsampler", 64)->sampleCount(), 64u);
}

TEST(Samplers, DeterministicPerSeedAndPixel) {
  for (const char* name : {"stratified", "ldsampler"}) {
    SCOPED_TRACE(name);
    auto a = makeSampler(name, 16)->clone(), b = makeSampler(name, 16)->clone();
    drawPixel(*b, 1, 1);  // a different history must not matter
    PixelSamples first = drawPixel(*a, 7, 42), again = drawPixel(*b, 7, 42);
    PixelSamples otherPixel = drawPixel(*a, 7, 43), otherSeed = drawPixel(*a, 8, 42);
    for (size_t d = 0; d < first.dims2D.size(); ++d)
      for (size_t s = 0; s < first.dims2D[d].size(); ++s) {
        EXPECT_EQ(first.dims2D[d][s].x, again.dims2D[d][s].x);
        EXPECT_EQ(first.dims2D[d][s].y, again.dims2D[d][s].y);
      }
    EXPECT_NE(first.dims2D[1][0].x, otherPixel.dims2D[1][0].x);
    EXPECT_NE(first.dims2D[1][0].x, otherSeed.dims2D[1][0].x);
  }
}

TEST(Samplers, ASamplesNumbersDoNotDependOnHowManyEarlierSamplesUsed) {
  // Paths of different lengths use different counts of numbers; a transient
  // render split into time windows relies on the next sample not noticing
  // (docs/transient-film.md, "Splitting a render").
  for (const char* name : {"independent", "stratified", "ldsampler"}) {
    SCOPED_TRACE(name);
    auto sampler = makeSampler(name, 4)->clone();
    auto secondSample = [&](int usedByFirst) {
      sampler->startPixel(5, 17);
      for (int i = 0; i < usedByFirst; ++i) sampler->next1D();
      sampler->advance();
      std::vector<float> values;
      for (int i = 0; i < 6; ++i) values.push_back(sampler->next1D());
      return values;
    };
    std::vector<float> shortPath = secondSample(3);
    EXPECT_EQ(shortPath, secondSample(40));
    EXPECT_EQ(shortPath, secondSample(0));
    // (One stream per pixel fails the checks above: the second sample's
    // numbers would continue where the first sample stopped.) Advancing
    // does give new numbers:
    sampler->startPixel(5, 17);
    std::vector<float> firstSample;
    for (int i = 0; i < 6; ++i) firstSample.push_back(sampler->next1D());
    EXPECT_NE(shortPath, firstSample);
  }
}

TEST(Samplers, UniformOverManyPixels) {
  // Pool dimension 2 (a padded one) of many pixels on a 7 x 7 grid, which is
  // not aligned with the strata, and compare with the uniform density.
  const int pixels = 4000, cells = 7;
  const double alpha = sidakSignificance(0.01, 4);
  for (const char* name : {"stratified", "ldsampler"}) {
    auto sampler = makeSampler(name, 16)->clone();
    std::vector<double> observed2D(cells * cells, 0.0), observed1D(cells * cells, 0.0);
    double n = 0;
    for (int p = 0; p < pixels; ++p) {
      PixelSamples px = drawPixel(*sampler, 11, uint64_t(p));
      for (size_t s = 0; s < px.dims2D[2].size(); ++s) {
        const Point2f& q = px.dims2D[2][s];
        observed2D[size_t(int(q.y * cells) * cells + int(q.x * cells))] += 1;
        // 1D dimensions 0 and 1 as a 2D point: also tests their independence.
        observed1D[size_t(int(px.dims1D[1][s] * cells) * cells + int(px.dims1D[0][s] * cells))] += 1;
        n += 1;
      }
    }
    std::vector<double> expected(cells * cells, n / (cells * cells));
    for (const auto* observed : {&observed2D, &observed1D}) {
      ChiSquareResult r = chiSquareTest(*observed, expected);
      EXPECT_GT(r.pValue, alpha) << name << ": " << r.message;
    }
  }
}

TEST(Samplers, LowerIntegrationErrorThanIndependentOnASmoothIntegrand) {
  // f(x, y) = exp(x) sin(pi y) over [0,1]^2 has integral (e - 1) * 2 / pi.
  // The mean squared error of a pixel's 16-sample estimate, averaged over
  // 2000 pixels, must be well below the independent sampler's: for a smooth
  // integrand stratification reduces the variance by a factor of the order of
  // the sample count, so "half" leaves a wide statistical margin.
  const double exact = (std::exp(1.0) - 1.0) * 2.0 / Pi;
  auto mse = [&](const char* name) {
    auto sampler = makeSampler(name, 16)->clone();
    double sum = 0.0;
    const int pixels = 2000;
    for (int p = 0; p < pixels; ++p) {
      PixelSamples px = drawPixel(*sampler, 5, uint64_t(p));
      double estimate = 0.0;
      for (const Point2f& q : px.dims2D[1]) estimate += std::exp(double(q.x)) * std::sin(Pi * double(q.y));
      estimate /= double(px.dims2D[1].size());
      sum += (estimate - exact) * (estimate - exact);
    }
    return sum / pixels;
  };
  double independent = mse("independent");
  for (const char* name : {"stratified", "ldsampler"}) {
    double error = mse(name);
    EXPECT_LT(error, 0.5 * independent) << name << ": MSE " << error << " vs independent " << independent;
  }
}

TEST(Samplers, StrataHoldOneSampleOfAPixelEachAndAreUniformOverPixels) {
  // Sampler::stratum: over a pixel's n samples exactly one value in each
  // [k/n, (k+1)/n), whatever numbers the samples drew; each sample's value
  // uniform over pixels (chi-square of sample 3's value, 10 cells); another
  // salt shifts the strata independently; the same (seed, pixel) repeats.
  const int pixels = 4000, cells = 10;
  const double alpha = sidakSignificance(0.01, 6);
  for (const char* name : {"independent", "stratified", "ldsampler"}) {
    for (int64_t n : {1, 4, 8}) {
      auto sampler = makeSampler(name, n)->clone();
      const uint32_t count = sampler->sampleCount();  // stratified rounds up to a square
      std::vector<double> observed(cells, 0.0);
      double sameStratum = 0.0;
      for (int p = 0; p < pixels; ++p) {
        sampler->startPixel(5, uint64_t(p));
        std::vector<int> perStratum(count, 0);
        for (uint32_t s = 0; s < count; ++s) {
          for (uint32_t k = 0; k <= s % 3; ++k) sampler->next1D();  // draws do not move the strata
          const float v = sampler->stratum(1), w = sampler->stratum(2);
          ASSERT_TRUE(v >= 0.0f && v < 1.0f && w >= 0.0f && w < 1.0f) << name << " " << v << " " << w;
          ++perStratum[std::min(uint32_t(v * float(count)), count - 1)];
          if (s == std::min<uint32_t>(3, count - 1)) observed[size_t(v * cells)] += 1;
          if (s == 0) sameStratum += int(v * 4) == int(w * 4);
          sampler->advance();
        }
        for (int c : perStratum) ASSERT_EQ(c, 1) << name << ", " << count << " samples, pixel " << p;
      }
      ChiSquareResult r = chiSquareTest(observed, std::vector<double>(cells, double(pixels) / cells));
      EXPECT_GT(r.pValue, alpha) << name << ", " << count << " samples: " << r.message;
      // Salts 1 and 2 land in the same quarter for a quarter of the pixels (independent shifts).
      EXPECT_NEAR(sameStratum / pixels, 0.25, 5 * std::sqrt(0.25 * 0.75 / pixels)) << name;
      sampler->startPixel(5, 17);
      const float first = sampler->stratum(1);
      sampler->startPixel(5, 17);
      EXPECT_EQ(sampler->stratum(1), first) << name;
    }
  }
}
