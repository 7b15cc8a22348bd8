#pragma once
// Per-channel comparison of colours with a tolerance relative to the
// expected value (absolute below 1), naming the channel on failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <femto/math/spectrum.h>

namespace femto::test {

inline void expectColorNear(const Color3f& actual, const Color3f& expected, float tolerance = 1e-6f) {
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(actual[c], expected[c], tolerance * std::max(1.0f, std::abs(expected[c])))
        << "channel " << c << " of " << actual;
}

}  // namespace femto::test
