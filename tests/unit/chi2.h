#pragma once
// Chi-square goodness-of-fit testing of sampling routines, after Mitsuba's
// approach (Jakob et al., mitsuba/python/chi2.py): draw many samples, histogram
// them over a 2D grid of the domain, integrate the claimed density over each
// cell numerically, pool cells with low expected counts, and compare the
// statistic with the chi-square distribution. Shared by the warp tests and,
// later, BSDF/emitter/phase-function tests.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <femto/math/constants.h>
#include <femto/math/pcg32.h>
#include <femto/math/vector.h>

namespace femto::test {

/// Regularised lower incomplete gamma P(a, x) by its power series
/// (Abramowitz & Stegun 6.5.29); converges quickly for x < a + 1.
inline double gammaPSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < 10000; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * 1e-15) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

/// Regularised upper incomplete gamma Q(a, x) by its continued fraction
/// (A&S 6.5.31), evaluated with the modified Lentz method; for x >= a + 1.
inline double gammaQContinuedFraction(double a, double x) {
  const double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 10000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

/// Q(a, x) = Gamma(a, x) / Gamma(a): the chi-square survival function is Q(dof/2, chi2/2).
inline double regularizedGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  return x < a + 1.0 ? 1.0 - gammaPSeries(a, x) : gammaQContinuedFraction(a, x);
}

/// Probability that a chi-square variable with `dof` degrees of freedom exceeds `statistic`.
inline double chiSquarePValue(double statistic, int dof) { return regularizedGammaQ(0.5 * dof, 0.5 * statistic); }

/// Per-test significance so that `testCount` independent tests together reject
/// a correct sampler with probability `alpha` (Sidak correction).
inline double sidakSignificance(double alpha, int testCount) { return 1.0 - std::pow(1.0 - alpha, 1.0 / testCount); }

struct ChiSquareResult {
  double statistic = 0.0;
  int dof = 0;
  double pValue = 0.0;
  std::string message;  // why it failed, or a summary
};

/// Compare observed counts with expected counts. Cells expecting fewer than
/// `minExpected` samples (including cells whose numerically integrated
/// density is zero but that a boundary of the support just clips) are pooled
/// into one, so the chi-square approximation holds.
inline ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                                     double minExpected = 5.0) {
  ChiSquareResult r;
  std::vector<size_t> order(expected.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });
  double pooledObserved = 0.0, pooledExpected = 0.0;
  int cells = 0;
  for (size_t i : order) {
    double o = observed[i], e = expected[i];
    if (e < minExpected) {
      pooledObserved += o;
      pooledExpected += e;
      continue;
    }
    if (pooledExpected > 0.0 && pooledExpected < minExpected) {
      // Keep pooling into this cell until the pool is large enough.
      pooledObserved += o;
      pooledExpected += e;
      continue;
    }
    r.statistic += (o - e) * (o - e) / e;
    ++cells;
  }
  if (pooledExpected > 0.0) {
    r.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++cells;
  }
  r.dof = cells - 1;
  if (r.dof < 1) {
    r.message = "too few cells with enough expected samples";
    r.pValue = 0.0;
    return r;
  }
  r.pValue = chiSquarePValue(r.statistic, r.dof);
  std::ostringstream os;
  os << "chi2 = " << r.statistic << ", dof = " << r.dof << ", p = " << r.pValue;
  r.message = os.str();
  return r;
}

/// A rectangular parameter domain [x0, x1] x [y0, y1] divided into nx x ny
/// cells, with a map from parameters to the sampled quantity and the Jacobian
/// of that map (the density of samples in parameter space is pdf * jacobian).
template <typename Value>
struct GridDomain {
  double x0, x1, y0, y1;
  int nx, ny;
  std::function<Value(double, double)> fromParams;            // parameter point -> value
  std::function<std::optional<Point2f>(const Value&)> toParams;  // value -> parameter point (nullopt: outside)
  std::function<double(double, double)> jacobian;             // |d value / d params|
};

/// (theta, phi) grid over the sphere; value = unit vector, Jacobian sin(theta).
inline GridDomain<Vec3f> sphericalDomain(int nTheta, int nPhi) {
  GridDomain<Vec3f> d;
  d.x0 = 0.0; d.x1 = Pi; d.y0 = 0.0; d.y1 = 2.0 * Pi;
  d.nx = nTheta; d.ny = nPhi;
  d.fromParams = [](double theta, double phi) {
    return Vec3f(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
  };
  d.toParams = [](const Vec3f& v) -> std::optional<Point2f> {
    double len = std::sqrt(double(v.x) * v.x + double(v.y) * v.y + double(v.z) * v.z);
    if (!(std::abs(len - 1.0) < 1e-3)) return std::nullopt;  // not a unit vector: a bug in the sampler
    double theta = std::acos(std::clamp(v.z / len, -1.0, 1.0));
    double phi = std::atan2(double(v.y), double(v.x));
    if (phi < 0.0) phi += 2.0 * Pi;
    return Point2f(float(theta), float(phi));
  };
  d.jacobian = [](double theta, double) { return std::sin(theta); };
  return d;
}

/// (theta, phi) grid over the sphere whose theta grid has lines at the given
/// angles (radians, in (0, pi)): the ranges between them get cells in
/// proportion to their length, at least one each. Densities that jump along
/// a circle of constant theta (a BSDF at the horizon, or where a refracted
/// lobe ends) are then integrated without the large error the midpoint rule
/// makes in a cell the jump crosses.
inline GridDomain<Vec3f> sphericalDomainWithBreaks(std::vector<double> breaks, int nTheta, int nPhi) {
  breaks.push_back(0.0);
  breaks.push_back(Pi);
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end(), [](double a, double b) { return b - a < 1e-6; }), breaks.end());
  // Grid-line positions (in cells) of the breaks.
  std::vector<double> lines{0.0};
  for (size_t k = 1; k < breaks.size(); ++k)
    lines.push_back(lines.back() + std::max(1.0, std::round(nTheta * (breaks[k] - breaks[k - 1]) / Pi)));
  GridDomain<Vec3f> d = sphericalDomain(int(lines.back()), nPhi);
  d.x1 = lines.back();
  auto piece = [lines](double x) {
    return std::min(size_t(std::upper_bound(lines.begin(), lines.end(), x) - lines.begin()), lines.size() - 1) - 1;
  };
  auto thetaOf = [=](double x) {
    size_t k = piece(x);
    return breaks[k] + (x - lines[k]) / (lines[k + 1] - lines[k]) * (breaks[k + 1] - breaks[k]);
  };
  auto sphere = sphericalDomain(1, nPhi);
  d.fromParams = [=](double x, double phi) { return sphere.fromParams(thetaOf(x), phi); };
  d.toParams = [=](const Vec3f& v) -> std::optional<Point2f> {
    std::optional<Point2f> p = sphere.toParams(v);
    if (!p) return p;
    size_t k = std::min(size_t(std::upper_bound(breaks.begin(), breaks.end(), double(p->x)) - breaks.begin()),
                        breaks.size() - 1) - 1;
    double x = lines[k] + (p->x - breaks[k]) / (breaks[k + 1] - breaks[k]) * (lines[k + 1] - lines[k]);
    return Point2f(float(x), p->y);
  };
  d.jacobian = [=](double x, double) {
    size_t k = piece(x);
    return std::sin(thetaOf(x)) * (breaks[k + 1] - breaks[k]) / (lines[k + 1] - lines[k]);
  };
  return d;
}

/// Planar grid over [x0, x1] x [y0, y1]; value = the point itself.
inline GridDomain<Point2f> planarDomain(double x0, double x1, double y0, double y1, int nx, int ny) {
  GridDomain<Point2f> d;
  d.x0 = x0; d.x1 = x1; d.y0 = y0; d.y1 = y1;
  d.nx = nx; d.ny = ny;
  d.fromParams = [](double x, double y) { return Point2f(float(x), float(y)); };
  d.toParams = [](const Point2f& p) -> std::optional<Point2f> { return p; };
  d.jacobian = [](double, double) { return 1.0; };
  return d;
}

/// Integral of pdf * jacobian over each cell, by the midpoint rule on
/// `sub` x `sub` points per cell (fine enough for densities with
/// discontinuities along cell-crossing curves, such as a disk's rim).
template <typename Value>
std::vector<double> integrateCells(const GridDomain<Value>& d, const std::function<double(const Value&)>& pdf,
                                   int sub = 16) {
  std::vector<double> result(size_t(d.nx) * d.ny, 0.0);
  double cw = (d.x1 - d.x0) / d.nx, ch = (d.y1 - d.y0) / d.ny;
  double sw = cw / sub, sh = ch / sub;
  for (int j = 0; j < d.ny; ++j)
    for (int i = 0; i < d.nx; ++i) {
      double sum = 0.0;
      for (int b = 0; b < sub; ++b)
        for (int a = 0; a < sub; ++a) {
          double x = d.x0 + i * cw + (a + 0.5) * sw, y = d.y0 + j * ch + (b + 0.5) * sh;
          sum += pdf(d.fromParams(x, y)) * d.jacobian(x, y);
        }
      result[size_t(j) * d.nx + i] = sum * sw * sh;
    }
  return result;
}

/// Draw `sampleCount` samples with `sample(u)` (u uniform in [0,1)^2), and
/// test them against `pdf` over the grid `d`. A sampler may fail (nullopt):
/// such samples are not counted, so `pdf` must then integrate to the
/// probability of success (as a BSDF's pdf does when some sampled
/// directions are rejected, e.g. reflections below the horizon). A sample
/// outside the domain fails the test, and so do samples where `pdf` is zero,
/// beyond a tiny fraction allowed for round-off at the boundary of the support.
template <typename Value>
ChiSquareResult testSamplerAllowingFailures(const GridDomain<Value>& d,
                                            const std::function<std::optional<Value>(const Point2f&)>& sample,
                                            const std::function<double(const Value&)>& pdf, int sampleCount = 1000000,
                                            int integrationSubdivisions = 16, uint64_t seed = 1) {
  std::vector<double> observed(size_t(d.nx) * d.ny, 0.0);
  PCG32 rng(seed, 7);
  int impossible = 0;
  for (int k = 0; k < sampleCount; ++k) {
    Point2f u(rng.nextFloat(), rng.nextFloat());
    std::optional<Value> value = sample(u);
    if (!value) continue;
    if (!(pdf(*value) > 0.0)) ++impossible;
    std::optional<Point2f> p = d.toParams(*value);
    if (!p || !(p->x >= d.x0 && p->x <= d.x1 && p->y >= d.y0 && p->y <= d.y1)) {
      ChiSquareResult r;
      std::ostringstream os;
      os << "sample for u = " << u << " lies outside the domain";
      r.message = os.str();
      return r;
    }
    int i = std::clamp(int((p->x - d.x0) / (d.x1 - d.x0) * d.nx), 0, d.nx - 1);
    int j = std::clamp(int((p->y - d.y0) / (d.y1 - d.y0) * d.ny), 0, d.ny - 1);
    observed[size_t(j) * d.nx + i] += 1.0;
  }
  if (impossible > 1e-5 * sampleCount) {
    ChiSquareResult r;
    std::ostringstream os;
    os << impossible << " of " << sampleCount << " samples fall where the density is zero";
    r.message = os.str();
    return r;
  }
  std::vector<double> expected = integrateCells(d, pdf, integrationSubdivisions);
  for (double& e : expected) e *= sampleCount;
  return chiSquareTest(observed, expected);
}

/// As testSamplerAllowingFailures, for a sampler that always succeeds.
template <typename Value>
ChiSquareResult testSampler(const GridDomain<Value>& d, const std::function<Value(const Point2f&)>& sample,
                            const std::function<double(const Value&)>& pdf, int sampleCount = 1000000,
                            int integrationSubdivisions = 16, uint64_t seed = 1) {
  std::function<std::optional<Value>(const Point2f&)> always = [&](const Point2f& u) {
    return std::optional<Value>(sample(u));
  };
  return testSamplerAllowingFailures(d, always, pdf, sampleCount, integrationSubdivisions, seed);
}

}  // namespace femto::test
