// stratified_photons (photon_tracer.h, stratifiedDirection): the directions a
// pass's photons leave the emitters in are stratified, the beam photons and
// the rest apart. Checked: each group's first k^2 photons hold one point in
// each cell of the k x k grid, at the jitter within it; the rest are the
// jitter itself; over uniform jitter a group's points average to a uniform
// density (the pass keeps its expectation). Unbiasedness in renders: the
// closed-form and random-media tests run at defaults.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <transient_beams/photon_tracer.h>

using namespace femto;
using namespace femto::beams;

TEST(StratifiedDirection, EachGroupPutsOnePhotonInEveryCellAndTheRestAtTheJitter) {
  const uint64_t beamPhotons = 3000, photons = 30000;  // the fog box's counts: k = 54 and 164
  for (const auto& [first, n] : {std::pair<uint64_t, uint64_t>{0, beamPhotons}, {beamPhotons, photons - beamPhotons}}) {
    const uint64_t k = uint64_t(std::sqrt(double(n)));
    std::vector<int> count(size_t(k * k), 0);
    for (uint64_t j = 0; j < n; ++j) {
      // Away from the cells' edges, where float rounding of (cell + jitter) / k may cross them.
      const Point2f jitter(0.01f + 0.98f * float((j * 37) % 101) / 101.0f, 0.01f + 0.98f * float((j * 59) % 97) / 97.0f);
      const Point2f u = stratifiedDirection(first + j, beamPhotons, photons, jitter);
      if (j >= k * k) {
        EXPECT_EQ(u.x, jitter.x);
        EXPECT_EQ(u.y, jitter.y);
        continue;
      }
      const uint64_t cx = uint64_t(u.x * float(k)), cy = uint64_t(u.y * float(k));
      ASSERT_LT(cx, k);
      ASSERT_LT(cy, k);
      ++count[size_t(cy * k + cx)];
      // At the jitter within its cell.
      EXPECT_NEAR(u.x * float(k) - float(cx), jitter.x, 1e-3f) << j;
      EXPECT_NEAR(u.y * float(k) - float(cy), jitter.y, 1e-3f) << j;
    }
    for (size_t c = 0; c < count.size(); ++c) EXPECT_EQ(count[c], 1) << "group from " << first << ", cell " << c;
  }
}

TEST(StratifiedDirection, AGroupAveragesToTheUniformDensity) {
  // Over many uniform jitters, the mean of f(u) over a group's photons equals
  // f's integral over the square (here f = x^2 y: 1/6), within 5 standard
  // errors: every cell is chosen exactly once, each with probability 1/k^2.
  const uint64_t n = 1000;  // k = 31: 961 stratified, 39 not
  uint64_t state = 12345;
  auto uniform = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return float(state >> 40) * 0x1p-24f;
  };
  constexpr int Trials = 400;
  double sum = 0.0, square = 0.0;
  for (int t = 0; t < Trials; ++t) {
    double mean = 0.0;
    for (uint64_t j = 0; j < n; ++j) {
      const Point2f u = stratifiedDirection(j, n, n, Point2f(uniform(), uniform()));
      mean += double(u.x) * u.x * u.y;
    }
    mean /= double(n);
    sum += mean, square += mean * mean;
  }
  const double mean = sum / Trials, se = std::sqrt((square / Trials - mean * mean) / (Trials - 1));
  EXPECT_NEAR(mean, 1.0 / 6.0, 5 * se + 1e-9);
}
