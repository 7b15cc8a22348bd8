#pragma once
// Doubles rounded to floats in a safe direction, for bounds kept in float
// (the beam map's and the surface photon map's time-gating bounds): a bound
// rounded the other way could prune what the double would keep.
#include <cmath>
#include <limits>

namespace femto::beams {

/// The smallest float >= x (x finite).
inline float floatAtLeast(double x) {
  float f = float(x);
  if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

/// The largest float <= x; -infinity for NaN (nothing is pruned).
inline float floatAtMost(double x) {
  if (std::isnan(x)) return -std::numeric_limits<float>::infinity();
  float f = float(x);
  if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  return f;
}

}  // namespace femto::beams
