#include <femto/view/exposure.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <femto/math/spectrum.h>
#include <femto/view/running_integral.h>
#include <femto/film/volume_scan.h>

namespace femto {

float luminanceOf(const float* rgb) { return Color3f(rgb[0], rgb[1], rgb[2]).luminance(); }

void LuminanceHistogram::add(float value) {
  if (!(value > 0.0f) || !std::isfinite(value)) return;
  const double position = (std::log2(double(value)) - MinExponent) * BucketsPerOctave;
  const int bucket = int(std::clamp(std::floor(position), 0.0, double(Buckets - 1)));
  ++buckets_[size_t(bucket)];
  ++count_;
}

float LuminanceHistogram::percentile(double percent) const {
  if (count_ == 0) return 0.0f;
  // The rank of the wanted value among the sorted counted values (1-based).
  const double rank = std::clamp(percent / 100.0, 0.0, 1.0) * double(count_);
  uint64_t below = 0;
  for (int i = 0; i < Buckets; ++i) {
    below += buckets_[size_t(i)];
    if (double(below) >= rank && below > 0)
      return float(std::exp2(MinExponent + (i + 0.5) / BucketsPerOctave));
  }
  return float(std::exp2(double(MaxExponent)));  // unreachable: below == count_ >= rank
}

LuminanceHistogram volumeLuminances(const NpyVolume& volume, int binBegin, int binEnd, bool cumulative,
                                    const Bitmap* before) {
  LuminanceHistogram histogram;
  const int bins = volume.bins();
  std::vector<float> sums;
  forEachPixelRun(volume, VolumeReadBudgetBytes, [&](int y, int x, int count, const float* data) {
    for (int p = 0; p < count; ++p) {
      const float* pixel = data + size_t(p) * bins * 3;
      if (cumulative) {
        sums.resize(size_t(bins) * 3);
        runningIntegral(pixel, bins, sums.data(), before ? before->pixel(x + p, y) : nullptr);
        pixel = sums.data();
      }
      for (int b = binBegin; b < binEnd; ++b) histogram.add(luminanceOf(pixel + size_t(b) * 3));
    }
  });
  return histogram;
}

float exposureForWhite(float white) { return white > 0.0f ? -std::log2(white) : 0.0f; }

}  // namespace femto
