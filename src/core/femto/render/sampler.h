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

  uint32_t sampleCount() const { return sampleCount_; }
  void setSampleCount(uint32_t n) { sampleCount_ = n; }
  /// The seed the camera samples start from for a render seeded `renderSeed`
  /// (--seed): that seed itself, combined with the scene's `seed` parameter
  /// (Mitsuba 3) when it gives a non-zero one.
  uint64_t cameraSeed(uint64_t renderSeed) const;

 private:
  uint32_t sampleCount_ = 4;
  uint64_t sceneSeed_ = 0;
};

/// Hash two 64-bit values into a well-mixed seed (splitmix64 finaliser).
uint64_t mixSeed(uint64_t a, uint64_t b);

}  // namespace femto
