#include <femto/analysis/image_metrics.h>

#include <cmath>
#include <limits>

#include <femto/base/error.h>

namespace femto {

void ErrorAccumulator::merge(const ErrorAccumulator& o) {
  sumSquared_ += o.sumSquared_;
  sumRelative_ += o.sumRelative_;
  sumAbsolute_ += o.sumAbsolute_;
  if (!(o.maxError_ <= maxError_) && !std::isnan(maxError_)) maxError_ = o.maxError_;
  if (o.peak_ > peak_) peak_ = o.peak_;
  count_ += o.count_;
}

ErrorMetrics ErrorAccumulator::metrics() const {
  ErrorMetrics m;
  m.count = count_;
  m.maxError = maxError_;
  m.referencePeak = peak_;
  if (count_ == 0) return m;
  const double n = double(count_);
  m.mse = sumSquared_ / n;
  m.relMse = sumRelative_ / n;
  m.mae = sumAbsolute_ / n;
  return m;
}

ErrorMetrics errorMetrics(std::span<const float> reference, std::span<const float> test, double epsilon) {
  if (reference.size() != test.size())
    throw Error(str("cannot compare ", reference.size(), " reference values with ", test.size(), " test values"));
  ErrorAccumulator acc(epsilon);
  acc.add(reference.data(), test.data(), reference.size());
  return acc.metrics();
}

double mse(std::span<const float> reference, std::span<const float> test) { return errorMetrics(reference, test).mse; }
double relMse(std::span<const float> reference, std::span<const float> test, double epsilon) {
  return errorMetrics(reference, test, epsilon).relMse;
}
double mae(std::span<const float> reference, std::span<const float> test) { return errorMetrics(reference, test).mae; }
double maxError(std::span<const float> reference, std::span<const float> test) {
  return errorMetrics(reference, test).maxError;
}

double psnr(double mse, double peak) {
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / mse);
}

}  // namespace femto
