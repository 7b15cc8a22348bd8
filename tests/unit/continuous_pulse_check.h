#pragma once
// Continuous emission (pulse "continuous") against the Dirac render of the
// same camera samples on the same time axis: shared by the pulse tests
// (test_transient_path_pulses.cpp) and the seed scenes' (test_seed_scenes.cpp).
#include <gtest/gtest.h>

#include <sstream>
#include <vector>

#include <femto/image/image_io.h>

namespace femto::test {

/// Bin i of a continuous render averages the running integral over the bin
/// (docs/transient-film.md, "Emitter pulses"), so it lies between the Dirac
/// level at the bin's start and at its end: `diracBefore` plus the Dirac
/// bins up to i-1, resp. up to i; per pixel and channel of the (h, w, bins, 3)
/// volumes, within float rounding (1e-5 of `scale`, the brightest steady
/// value, plus 1e-7). Fails naming the first bin outside and the count.
inline ::testing::AssertionResult isRunningIntegralOf(const std::vector<float>& continuous,
                                                      const std::vector<float>& dirac, const Bitmap& diracBefore,
                                                      int w, int h, int bins, double scale) {
  const double slack = 1e-5 * scale + 1e-7;
  if (continuous.size() != dirac.size() || dirac.size() != size_t(h) * w * bins * 3)
    return ::testing::AssertionFailure() << "volumes of different shapes";
  size_t outside = 0;
  std::ostringstream first;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        double running = diracBefore.pixel(x, y)[c];
        for (int b = 0; b < bins; ++b) {
          const size_t i = ((size_t(y) * w + x) * bins + b) * 3 + c;
          const double next = running + dirac[i], v = continuous[i];
          if (v < running - slack || v > next + slack) {
            if (outside++ == 0)
              first << "pixel " << x << "," << y << " channel " << c << " bin " << b << ": " << v << " not in ["
                    << running << ", " << next << "]";
          }
          running = next;
        }
      }
  if (outside == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << outside << " bins outside the running integral's bounds; first: " << first.str();
}

}  // namespace femto::test
