#pragma once
// Piecewise-constant densities for importance sampling tabulated functions
// (environment maps, emission over mesh triangles, photon emission).
// Construction follows Pharr, Jakob and Humphreys, "Physically Based
// Rendering" (3rd ed.), sec. 13.6.7 (1D) and 13.6.7.1 (2D, marginal rows times
// conditional columns). tests/unit/math/test_distribution.cpp checks each sampler
// against its pdf with a chi-square test.
#include <cstddef>
#include <vector>

#include <femto/math/vector.h>

namespace femto {

/// A step function over [0, 1) with `n` equal bins, normalised into a density.
/// Weights must be finite and >= 0. When all are zero the distribution is
/// uniform (so sampling stays well defined) and integral() reports 0.
class Distribution1D {
 public:
  Distribution1D() = default;
  /// Throws femto::Error for an empty, negative or non-finite weight list.
  explicit Distribution1D(std::vector<float> weights);

  size_t size() const { return weights_.size(); }
  /// Integral of the step function over [0, 1): the mean weight.
  float integral() const { return integral_; }
  /// Probability of bin `i`.
  float probability(size_t i) const;
  /// Density on [0, 1) at x (bins are 1/n wide).
  float pdf(float x) const;

  /// Pick a bin with probability proportional to its weight. `uRemapped`
  /// (optional) receives u's position inside the bin's CDF interval, a fresh
  /// uniform variable in [0, 1).
  size_t sampleDiscrete(float u, float* probability = nullptr, float* uRemapped = nullptr) const;
  /// Sample x in [0, 1) with density pdf(x); `bin` (optional) receives its bin.
  float sampleContinuous(float u, float* pdf = nullptr, size_t* bin = nullptr) const;

 private:
  std::vector<float> weights_;
  std::vector<double> cdf_;  // size n + 1, cdf_[0] = 0, cdf_[n] = 1
  float integral_ = 0.0f;
};

/// A step function over [0, 1)^2 on a width x height grid, cell (col, row) =
/// weights[row * width + col], sampled as a marginal over rows (y) times the
/// conditional over columns (x) of the chosen row.
class Distribution2D {
 public:
  Distribution2D() = default;
  /// Throws femto::Error when the size does not match or a weight is bad.
  Distribution2D(const std::vector<float>& weights, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  /// Integral over [0, 1)^2 (the mean weight).
  float integral() const { return marginal_.integral(); }
  /// Sample p in [0, 1)^2 with density pdf(p) (w.r.t. area on the unit square).
  Point2f sample(const Point2f& u, float* pdf = nullptr) const;
  float pdf(const Point2f& p) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<Distribution1D> rows_;  // conditional density of x in each row
  Distribution1D marginal_;           // density of y
};

}  // namespace femto
