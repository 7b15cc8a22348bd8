#pragma once
// Error metrics between a reference and a test rendering, over any set of
// float values (pixels x channels of an image, or pixels x bins x channels of
// a transient volume). Every formula is in docs/compare.md. Sums are in
// double and values are fed one at a time, so volumes far larger than memory
// can be measured while they are streamed from disk.
#include <cmath>
#include <cstddef>
#include <span>

namespace femto {

/// The epsilon of relMSE: keeps the relative error of near-black reference
/// values finite; 1e-2 is the usual choice in the rendering literature on
/// adaptive sampling and denoising, where relMSE is the standard metric.
inline constexpr double DefaultRelMseEpsilon = 1e-2;

/// (t - r)^2
inline double squaredError(double r, double t) { return (t - r) * (t - r); }
/// (t - r)^2 / (r^2 + epsilon)
inline double relativeSquaredError(double r, double t, double epsilon) { return squaredError(r, t) / (r * r + epsilon); }
/// |t - r|
inline double absoluteError(double r, double t) { return t > r ? t - r : r - t; }

struct ErrorMetrics {
  size_t count = 0;         // values compared
  double mse = 0.0;         // mean squared error
  double relMse = 0.0;      // mean relative squared error
  double mae = 0.0;         // mean absolute error
  double maxError = 0.0;    // largest absolute error
  double referencePeak = 0.0;  // largest reference value (PSNR's peak)
};

/// Running sums of the error terms; add values in any grouping, merge partial
/// sums, read the means at the end.
class ErrorAccumulator {
 public:
  explicit ErrorAccumulator(double epsilon = DefaultRelMseEpsilon) : epsilon_(epsilon) {}
  void add(double r, double t) {
    sumSquared_ += squaredError(r, t);
    sumRelative_ += relativeSquaredError(r, t, epsilon_);
    double a = absoluteError(r, t);
    sumAbsolute_ += a;
    // A NaN makes the maximum NaN, and it stays NaN: never silently skipped.
    if (!(a <= maxError_) && !std::isnan(maxError_)) maxError_ = a;
    if (r > peak_) peak_ = r;
    ++count_;
  }
  void add(const float* r, const float* t, size_t n) {
    for (size_t i = 0; i < n; ++i) add(r[i], t[i]);
  }
  void merge(const ErrorAccumulator& other);
  ErrorMetrics metrics() const;

 private:
  double epsilon_;
  double sumSquared_ = 0.0, sumRelative_ = 0.0, sumAbsolute_ = 0.0, maxError_ = 0.0, peak_ = 0.0;
  size_t count_ = 0;
};

/// All metrics of `test` against `reference` (same length; an Error otherwise).
ErrorMetrics errorMetrics(std::span<const float> reference, std::span<const float> test,
                          double epsilon = DefaultRelMseEpsilon);

/// mean (t - r)^2
double mse(std::span<const float> reference, std::span<const float> test);
/// mean (t - r)^2 / (r^2 + epsilon)
double relMse(std::span<const float> reference, std::span<const float> test, double epsilon = DefaultRelMseEpsilon);
/// mean |t - r|
double mae(std::span<const float> reference, std::span<const float> test);
/// max |t - r|
double maxError(std::span<const float> reference, std::span<const float> test);
/// 10 log10(peak^2 / mse) in dB; +infinity when mse is 0.
double psnr(double mse, double peak);

}  // namespace femto
