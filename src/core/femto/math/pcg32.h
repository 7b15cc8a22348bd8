#pragma once
// PCG32 random number generator (O'Neill 2014, "PCG: A Family of Simple Fast
// Space-Efficient Statistically Good Algorithms for Random Number Generation"),
// pcg32 XSH-RR variant with selectable stream.
#include <cstdint>

namespace femto {

class PCG32 {
 public:
  PCG32() { seed(0x853c49e6748fea9bULL, 0xda3e39cb94b95bdbULL); }
  PCG32(uint64_t initState, uint64_t stream) { seed(initState, stream); }

  void seed(uint64_t initState, uint64_t stream = 1) {
    state_ = 0;
    inc_ = (stream << 1u) | 1u;
    nextUInt();
    state_ += initState;
    nextUInt();
  }
  uint32_t nextUInt() {
    uint64_t old = state_;
    state_ = old * 0x5851f42d4c957f2dULL + inc_;
    uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31));
  }
  /// Uniform in [0, bound) without modulo bias.
  uint32_t nextUInt(uint32_t bound) {
    uint32_t threshold = (~bound + 1u) % bound;
    for (;;) {
      uint32_t r = nextUInt();
      if (r >= threshold) return r % bound;
    }
  }
  /// Uniform float in [0, 1): 23 random mantissa bits.
  float nextFloat() {
    union { uint32_t u; float f; } x;
    x.u = (nextUInt() >> 9) | 0x3f800000u;
    return x.f - 1.0f;
  }
  /// Uniform double in [0, 1).
  double nextDouble() {
    union { uint64_t u; double d; } x;
    x.u = (uint64_t(nextUInt()) << 20) | 0x3ff0000000000000ULL;
    return x.d - 1.0;
  }
  /// Jump ahead (or back, with negative delta) in O(log n) (Brown 1994).
  void advance(int64_t delta);

 private:
  uint64_t state_ = 0, inc_ = 1;
};

inline void PCG32::advance(int64_t delta_) {
  uint64_t curMult = 0x5851f42d4c957f2dULL, curPlus = inc_, accMult = 1u, accPlus = 0u;
  uint64_t delta = uint64_t(delta_);
  while (delta > 0) {
    if (delta & 1) {
      accMult *= curMult;
      accPlus = accPlus * curMult + curPlus;
    }
    curPlus = (curMult + 1) * curPlus;
    curMult *= curMult;
    delta /= 2;
  }
  state_ = accMult * state_ + accPlus;
}

}  // namespace femto
