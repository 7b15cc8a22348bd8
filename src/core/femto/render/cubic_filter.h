#pragma once
// The Mitchell-Netravali family of cubic filters (Mitchell and Netravali,
// "Reconstruction Filters in Computer Graphics", SIGGRAPH 1988, eq. 8),
// defined over |x| < 2; shared by the mitchell and catmullrom pixel filters.
#include <cmath>

#include <femto/render/rfilter.h>

namespace femto {

class CubicFilter {
 public:
  CubicFilter(float b, float c) : b_(b), c_(c) {}

  float operator()(float x) const {
    x = std::abs(x);
    const float b = b_, c = c_;
    if (x < 1.0f)
      return ((12.0f - 9.0f * b - 6.0f * c) * x * x * x + (-18.0f + 12.0f * b + 6.0f * c) * x * x + (6.0f - 2.0f * b)) /
             6.0f;
    if (x < 2.0f)
      return ((-b - 6.0f * c) * x * x * x + (6.0f * b + 30.0f * c) * x * x + (-12.0f * b - 48.0f * c) * x +
              (8.0f * b + 24.0f * c)) /
             6.0f;
    return 0.0f;
  }

  float b() const { return b_; }
  float c() const { return c_; }

 private:
  float b_, c_;
};

}  // namespace femto
