#pragma once
// One exposure for a whole transient sequence: the luminance that the chosen
// percentile of all voxels reaches is mapped to white. Transient volumes have
// a huge dynamic range (the direct wavefront against late, dim multiple
// scattering), so a per-frame exposure would make every frame look equally
// bright and hide exactly what the sequence is meant to show.
#include <array>
#include <cstdint>

#include <femto/image/image_io.h>
#include <femto/film/npy_volume.h>

namespace femto {

/// Rec. 709 luminance of a linear RGB triple.
float luminanceOf(const float* rgb);

/// Percentiles of a stream of positive values in fixed memory: a histogram
/// over log2(value) with BucketsPerOctave buckets per octave covering all
/// positive normal floats, so a percentile is exact to a factor 2^(1/32)
/// (about 2 %) however many values were added. Zero, negative and non-finite
/// values are not counted (most voxels of a transient volume are black before
/// the light arrives; counting them would push any percentile to zero).
class LuminanceHistogram {
 public:
  static constexpr int BucketsPerOctave = 32;
  static constexpr int MinExponent = -126, MaxExponent = 128;

  void add(float value);
  uint64_t count() const { return count_; }
  /// The value below which `percent` % of the counted values lie (the
  /// geometric centre of its bucket); 0 when nothing was counted.
  float percentile(double percent) const;

 private:
  static constexpr int Buckets = (MaxExponent - MinExponent) * BucketsPerOctave;
  std::array<uint64_t, Buckets> buckets_{};
  uint64_t count_ = 0;
};

/// Luminance histogram of bins [binBegin, binEnd) of `volume`, read with
/// bounded memory. `cumulative`: of the running integral over time instead
/// (see running_integral.h), summed from bin 0 on top of `before` (the light
/// that arrived before the window) when given.
LuminanceHistogram volumeLuminances(const NpyVolume& volume, int binBegin, int binEnd, bool cumulative,
                                    const Bitmap* before = nullptr);

/// The exposure, in stops (as writePNG takes it), that maps `white` to 1;
/// 0 when `white` is not positive (an all-black volume).
float exposureForWhite(float white);

}  // namespace femto
