#include <femto/math/distribution.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>

namespace femto {
namespace {

// Largest float below 1: keeps samples in [0, 1) after round-off.
constexpr float OneMinusEpsilon = 0.99999994f;

size_t binOf(float x, size_t n) { return std::min(size_t(std::max(0.0f, x) * float(n)), n - 1); }

}  // namespace

Distribution1D::Distribution1D(std::vector<float> weights) : weights_(std::move(weights)) {
  if (weights_.empty()) throw Error("a sampling distribution needs at least one weight");
  const size_t n = weights_.size();
  cdf_.assign(n + 1, 0.0);
  for (size_t i = 0; i < n; ++i) {
    if (!(weights_[i] >= 0.0f) || !std::isfinite(weights_[i]))
      throw Error(str("sampling distribution weight ", i, " is ", weights_[i], " (must be finite and >= 0)"));
    cdf_[i + 1] = cdf_[i] + double(weights_[i]);  // double: long tables (big env maps) lose no mass
  }
  double sum = cdf_[n];
  integral_ = float(sum / double(n));
  for (size_t i = 1; i <= n; ++i) cdf_[i] = sum > 0.0 ? cdf_[i] / sum : double(i) / double(n);
  cdf_[n] = 1.0;
}

float Distribution1D::probability(size_t i) const {
  if (i >= weights_.size()) return 0.0f;
  return float(cdf_[i + 1] - cdf_[i]);
}

float Distribution1D::pdf(float x) const {
  if (weights_.empty() || !(x >= 0.0f && x < 1.0f)) return 0.0f;
  return probability(binOf(x, size())) * float(size());
}

size_t Distribution1D::sampleDiscrete(float u, float* probability, float* uRemapped) const {
  // First bin whose upper CDF edge lies above u; bins of zero width are never chosen.
  auto it = std::upper_bound(cdf_.begin() + 1, cdf_.end(), double(u));
  size_t i = std::min(size_t(it - cdf_.begin()) - 1, size() - 1);
  while (i > 0 && cdf_[i + 1] == cdf_[i]) --i;  // u == 1 round-off: step back onto a bin with mass
  double width = cdf_[i + 1] - cdf_[i];
  if (probability) *probability = float(width);
  if (uRemapped) *uRemapped = std::clamp(float((double(u) - cdf_[i]) / width), 0.0f, OneMinusEpsilon);
  return i;
}

float Distribution1D::sampleContinuous(float u, float* pdf, size_t* bin) const {
  float within = 0.0f, p = 0.0f;
  size_t i = sampleDiscrete(u, &p, &within);
  if (pdf) *pdf = p * float(size());
  if (bin) *bin = i;
  return std::min((float(i) + within) / float(size()), OneMinusEpsilon);
}

Distribution2D::Distribution2D(const std::vector<float>& weights, int width, int height)
    : width_(width), height_(height) {
  if (width <= 0 || height <= 0 || weights.size() != size_t(width) * size_t(height))
    throw Error(str("a 2D sampling distribution of ", width, " x ", height, " needs that many weights, got ",
                    weights.size()));
  rows_.reserve(size_t(height));
  std::vector<float> rowIntegrals(static_cast<size_t>(height), 0.0f);
  for (int y = 0; y < height; ++y) {
    rows_.emplace_back(std::vector<float>(weights.begin() + ptrdiff_t(y) * width, weights.begin() + ptrdiff_t(y + 1) * width));
    rowIntegrals[size_t(y)] = rows_.back().integral();
  }
  marginal_ = Distribution1D(std::move(rowIntegrals));
}

Point2f Distribution2D::sample(const Point2f& u, float* pdf) const {
  float pdfY = 0.0f, pdfX = 0.0f;
  size_t row = 0;
  float y = marginal_.sampleContinuous(u.y, &pdfY, &row);
  float x = rows_[row].sampleContinuous(u.x, &pdfX);
  if (pdf) *pdf = pdfX * pdfY;
  return {x, y};
}

float Distribution2D::pdf(const Point2f& p) const {
  if (!(p.y >= 0.0f && p.y < 1.0f)) return 0.0f;
  float pdfY = marginal_.pdf(p.y);
  return pdfY > 0.0f ? pdfY * rows_[binOf(p.y, size_t(height_))].pdf(p.x) : 0.0f;
}

}  // namespace femto
