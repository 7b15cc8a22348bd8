#pragma once
// Building blocks of the stratified and low-discrepancy samplers: counter-
// based hashing (every value is a pure function of seed, pixel, dimension
// and sample index, so images do not depend on thread count or tile order),
// random permutations computed one element at a time, and Owen-scrambled
// (0,2)-sequence points.
#include <cstdint>

#include <femto/render/sampler.h>

namespace femto {
namespace sequence {

/// A uniform float in [0, 1) from the high 24 bits of `bits`.
inline float toUnitFloat(uint32_t bits) { return float(bits >> 8) * 0x1p-24f; }

/// Smallest all-ones mask covering n - 1 (n >= 1).
inline uint32_t coveringMask(uint32_t n) {
  uint32_t m = n - 1;
  m |= m >> 1, m |= m >> 2, m |= m >> 4, m |= m >> 8, m |= m >> 16;
  return m;
}

/// Element i of a random permutation of [0, n) chosen by `key`, in O(1)
/// expected time: a keyed bijection of the smallest power-of-two domain
/// covering n, iterated until it lands inside [0, n) ("cycle walking", as in
/// Kensler 2013, "Correlated Multi-Jittered Sampling", sec. 3). Each step is
/// invertible on w-bit values: xor with a constant, multiplication by an odd
/// constant modulo 2^w, and x ^= x >> s.
inline uint32_t permuteIndex(uint32_t i, uint32_t n, uint64_t key) {
  if (n <= 1) return 0;
  const uint32_t mask = coveringMask(n);
  const int half = (__builtin_popcount(mask) + 1) / 2;
  const uint32_t k0 = uint32_t(key), k1 = uint32_t(key >> 32);
  const uint32_t k2 = uint32_t(mixSeed(key, 0x51ed27u)), k3 = uint32_t(mixSeed(key, 0x2545f491u));
  uint32_t x = i;
  do {
    x = (x ^ k0) & mask;
    x = (x * (k1 | 1u)) & mask;
    x ^= x >> half;
    x = (x ^ k2) & mask;
    x = (x * 0x9e3779b1u) & mask;
    x ^= x >> half;
    x = (x + k3) & mask;
    x = (x * (k3 | 1u)) & mask;
    x ^= x >> half;
  } while (x >= n);
  return x;
}

inline uint32_t reverseBits(uint32_t x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
  return x;
}

/// First coordinate of the (0,2)-sequence: the base-2 radical inverse (van
/// der Corput), as 32 fraction bits.
inline uint32_t vanDerCorput(uint32_t i) { return reverseBits(i); }

/// Second coordinate: Sobol's second dimension, whose generator matrix is
/// Pascal's triangle mod 2; together with van der Corput it forms a
/// (0,2)-sequence in base 2 (Kollig and Keller 2002, "Efficient multidimensional
/// sampling", sec. 3).
inline uint32_t sobol2(uint32_t i) {
  uint32_t result = 0;
  for (uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
    if (i & 1u) result ^= v;
  return result;
}

/// Owen's nested uniform scrambling of a 32-bit fraction (Owen 1995): each
/// digit is flipped by a random function of the digits above it. In bit-
/// reversed order, "the digits above" are the lower bits, and x ^= x * c with
/// an even c, or x += c, changes bit k only as a function of bits below k:
/// a hash-based scramble in the manner of Laine and Karras (2011) and Burley
/// (2020, "Practical Hash-based Owen Scrambling"), here with multipliers drawn
/// from the key. It keeps every elementary interval of a net occupied.
inline uint32_t owenScramble(uint32_t fraction, uint64_t key) {
  uint32_t x = reverseBits(fraction);
  const uint64_t a = mixSeed(key, 1), b = mixSeed(key, 2);
  x += uint32_t(key);
  x ^= x * (uint32_t(a) << 1);
  x ^= x * (uint32_t(a >> 32) << 1);
  x += uint32_t(key >> 32);
  x ^= x * (uint32_t(b) << 1);
  x ^= x * (uint32_t(b >> 32) << 1);
  return reverseBits(x);
}

}  // namespace sequence

/// Base of samplers that treat every next1D/next2D call of a sample as its
/// own dimension: keeps the per-pixel key, the sample index and the
/// dimension counter, and restarts the dimensions at each sample.
class DimensionalSampler : public Sampler {
 public:
  using Sampler::Sampler;
  void startPixel(uint64_t seed, uint64_t pixelIndex) override {
    markPixel(seed, pixelIndex);
    pixelKey_ = mixSeed(seed, pixelIndex);
    sampleIndex_ = 0;
    dimension_ = 0;
  }
  void advance() override {
    markSample();
    ++sampleIndex_;
    dimension_ = 0;
  }

 protected:
  /// A key for the next dimension of this pixel (the same for every sample).
  uint64_t nextDimensionKey() { return mixSeed(pixelKey_, dimension_++); }
  /// Uniform bits specific to (pixel, dimension key, sample, stream).
  uint32_t randomBits(uint64_t dimensionKey, uint32_t stream) const {
    return uint32_t(mixSeed(mixSeed(dimensionKey, sampleIndex_), stream) >> 32);
  }
  uint32_t sampleIndex() const { return sampleIndex_; }

 private:
  uint64_t pixelKey_ = 0;
  uint32_t sampleIndex_ = 0, dimension_ = 0;
};

}  // namespace femto
