// Every warp in math/warp.h against its density: a chi-square goodness-of-fit
// test (see chi2.h) and a check that the density integrates to one.
#include <gtest/gtest.h>

#include <femto/math/warp.h>

#include "chi2.h"

using namespace femto;
using namespace femto::test;

namespace {

// Number of chi-square tests in this file, for the Sidak correction: together
// they reject correct warps with probability 1%.
constexpr int ChiSquareTests = 7;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

using DirectionFn = std::function<Vec3f(const Point2f&)>;
using DirectionPdf = std::function<double(const Vec3f&)>;

void expectDirectionalWarpFits(const DirectionFn& sample, const DirectionPdf& pdf) {
  GridDomain<Vec3f> domain = sphericalDomain(24, 48);
  ChiSquareResult r = testSampler<Vec3f>(domain, sample, pdf);
  EXPECT_GT(r.pValue, Significance) << r.message;
  std::vector<double> cells = integrateCells<Vec3f>(domain, pdf);
  EXPECT_NEAR(std::accumulate(cells.begin(), cells.end(), 0.0), 1.0, 2e-3) << "pdf does not integrate to 1";
}

// Barycentric density of a uniform triangle sample: 1 / (area of the reference triangle).
double trianglePdf(const Point2f& b) { return (b.x >= 0 && b.y >= 0 && b.x + b.y <= 1) ? 2.0 : 0.0; }

}  // namespace

TEST(Warp, UniformDiskConcentric) {
  GridDomain<Point2f> domain = planarDomain(-1, 1, -1, 1, 40, 40);
  std::function<Point2f(const Point2f&)> sample = warp::squareToUniformDiskConcentric;
  std::function<double(const Point2f&)> pdf = [](const Point2f& p) { return double(warp::squareToUniformDiskPdf(p)); };
  ChiSquareResult r = testSampler<Point2f>(domain, sample, pdf, 1000000, 64);
  EXPECT_GT(r.pValue, Significance) << r.message;
  std::vector<double> cells = integrateCells<Point2f>(domain, pdf, 64);
  EXPECT_NEAR(std::accumulate(cells.begin(), cells.end(), 0.0), 1.0, 2e-3);
}

TEST(Warp, UniformDiskCentreMapsToCentre) {
  Point2f c = warp::squareToUniformDiskConcentric({0.5f, 0.5f});
  EXPECT_EQ(c.x, 0.0f);
  EXPECT_EQ(c.y, 0.0f);
}

TEST(Warp, UniformSphere) {
  expectDirectionalWarpFits(warp::squareToUniformSphere, [](const Vec3f& v) { return warp::squareToUniformSpherePdf(v); });
}

TEST(Warp, UniformHemisphere) {
  expectDirectionalWarpFits(warp::squareToUniformHemisphere,
                            [](const Vec3f& v) { return warp::squareToUniformHemispherePdf(v); });
}

TEST(Warp, CosineHemisphere) {
  expectDirectionalWarpFits(warp::squareToCosineHemisphere,
                            [](const Vec3f& v) { return warp::squareToCosineHemispherePdf(v); });
}

TEST(Warp, UniformConeNarrow) {
  const float cosCutoff = std::cos(degToRad(20.0f));
  // A finer theta grid so the 20 degree cone covers several rows of cells.
  GridDomain<Vec3f> domain = sphericalDomain(72, 32);
  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) { return warp::squareToUniformCone(u, cosCutoff); };
  std::function<double(const Vec3f&)> pdf = [&](const Vec3f& v) { return warp::squareToUniformConePdf(v, cosCutoff); };
  ChiSquareResult r = testSampler<Vec3f>(domain, sample, pdf);
  EXPECT_GT(r.pValue, Significance) << r.message;
  std::vector<double> cells = integrateCells<Vec3f>(domain, pdf, 32);
  EXPECT_NEAR(std::accumulate(cells.begin(), cells.end(), 0.0), 1.0, 2e-3);
}

TEST(Warp, UniformConeWide) {
  const float cosCutoff = std::cos(degToRad(120.0f));
  expectDirectionalWarpFits([&](const Point2f& u) { return warp::squareToUniformCone(u, cosCutoff); },
                            [&](const Vec3f& v) { return warp::squareToUniformConePdf(v, cosCutoff); });
}

TEST(Warp, UniformTriangle) {
  GridDomain<Point2f> domain = planarDomain(0, 1, 0, 1, 30, 30);
  std::function<Point2f(const Point2f&)> sample = warp::squareToUniformTriangle;
  std::function<double(const Point2f&)> pdf = trianglePdf;
  // The triangle's hypotenuse runs along cell diagonals: integrate finely so
  // the midpoint rule's error there stays well below the sampling noise.
  ChiSquareResult r = testSampler<Point2f>(domain, sample, pdf, 1000000, 64);
  EXPECT_GT(r.pValue, Significance) << r.message;
}

// The test machinery itself must be able to fail: a cosine sampler checked
// against the uniform hemisphere density is rejected.
TEST(Warp, ChiSquareRejectsAWrongDensity) {
  GridDomain<Vec3f> domain = sphericalDomain(24, 48);
  std::function<Vec3f(const Point2f&)> sample = warp::squareToCosineHemisphere;
  std::function<double(const Vec3f&)> pdf = [](const Vec3f& v) { return warp::squareToUniformHemispherePdf(v); };
  ChiSquareResult r = testSampler<Vec3f>(domain, sample, pdf, 100000);
  EXPECT_LT(r.pValue, 1e-6) << r.message;
}

TEST(Warp, ChiSquareRejectsSamplesWhereThePdfIsZero) {
  GridDomain<Vec3f> domain = sphericalDomain(12, 24);
  std::function<Vec3f(const Point2f&)> sample = warp::squareToUniformSphere;
  std::function<double(const Vec3f&)> pdf = [](const Vec3f& v) { return warp::squareToUniformHemispherePdf(v); };
  ChiSquareResult r = testSampler<Vec3f>(domain, sample, pdf, 10000);
  EXPECT_EQ(r.pValue, 0.0) << r.message;
}

TEST(ChiSquare, IncompleteGammaMatchesClosedForms) {
  // Q(1, x) = exp(-x); chi-square with 2 dof: P(X > s) = exp(-s / 2).
  for (double x : {0.1, 0.5, 1.0, 2.0, 5.0, 20.0}) EXPECT_NEAR(regularizedGammaQ(1.0, x), std::exp(-x), 1e-12);
  // Q(1/2, x) = erfc(sqrt(x)).
  for (double x : {0.01, 0.3, 1.2, 4.0, 30.0}) EXPECT_NEAR(regularizedGammaQ(0.5, x), std::erfc(std::sqrt(x)), 1e-12);
  // Median of chi-square with 100 dof is about 99.334 (tabulated).
  EXPECT_NEAR(chiSquarePValue(99.334, 100), 0.5, 1e-3);
  EXPECT_NEAR(sidakSignificance(0.01, 1), 0.01, 1e-15);
}
