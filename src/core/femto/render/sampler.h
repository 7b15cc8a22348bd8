#pragma once
// Sample generators. The scene's sampler is a prototype; the render loop
// clones one per thread and restarts it per pixel from (seed, pixel index), so
// the image does not depend on the thread count or tile order.
#include <cstdint>
#include <memory>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/math/vector.h>

namespace femto {

/// Hash two 64-bit values into a well-mixed seed (splitmix64 finaliser).
uint64_t mixSeed(uint64_t a, uint64_t b);

class Sampler : public Object {
 public:
  /// Reads "sample_count" (default 4).
  explicit Sampler(const Properties& props);
  ObjectKind kind() const override { return ObjectKind::Sampler; }

  virtual std::unique_ptr<Sampler> clone() const = 0;
  /// Start the sequence of pixel `pixelIndex`; deterministic in (seed, pixelIndex).
  virtual void startPixel(uint64_t seed, uint64_t pixelIndex) = 0;
  /// Move to the next sample of the current pixel.
  virtual void advance() = 0;
  virtual float next1D() = 0;
  virtual Point2f next2D() = 0;

  /// A uniform value in [0, 1) for a choice made once per sample (whether
  /// it gathers photons, say): the pixel's sample index over sampleCount(),
  /// shifted by a random offset of the pixel and `salt`. Each value is
  /// uniform on its own, and over a pixel's sampleCount() samples exactly
  /// one lies in each [k/n, (k+1)/n), so "stratum < q" picks q n of them
  /// (give or take one) instead of a binomial number. Samplers that do not
  /// mark their pixels and samples (markPixel, markSample) give all of a
  /// pixel's samples one value: still uniform, not stratified.
  float stratum(uint64_t salt) const;

  uint32_t sampleCount() const { return sampleCount_; }
  void setSampleCount(uint32_t n) { sampleCount_ = n; }
  /// The seed the camera samples start from for a render seeded `renderSeed`
  /// (--seed): that seed itself, combined with the scene's `seed` parameter
  /// (Mitsuba 3) when it gives a non-zero one.
  uint64_t cameraSeed(uint64_t renderSeed) const;

 protected:
  /// For stratum(): subclasses call these from startPixel() and advance().
  void markPixel(uint64_t seed, uint64_t pixelIndex) {
    stratumKey_ = mixSeed(seed, pixelIndex);
    stratumIndex_ = 0;
  }
  void markSample() { ++stratumIndex_; }

 private:
  uint64_t stratumKey_ = 0;
  uint32_t stratumIndex_ = 0;
  uint32_t sampleCount_ = 4;
  uint64_t sceneSeed_ = 0;
};

}  // namespace femto
