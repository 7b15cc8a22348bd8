// stratified_photons (photon_tracer.h, stratifiedEmission): a pass's photons
// leave their emitters along an Owen-scrambled Sobol sequence. Checked: the
// first 2^m photons' directions fill every elementary interval of a 2D net,
// each of the five numbers fills every 1/2^m, and no two of them crowd into
// the cells of a square grid (two coordinates drawn from the same sequence
// dimension would lie on a scrambled diagonal, 2^(m/2) points a cell: that
// made the ToF-Tungsten port 0.79x as efficient); each photon's numbers,
// over passes, are uniform and uncorrelated (the pass stays unbiased);
// passes differ. Unbiasedness in renders: the closed-form tests run at
// defaults.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <femto/render/sampler.h>
#include <femto/transport/sample_sequences.h>
#include <transient_beams/photon_tracer.h>

using namespace femto;
using namespace femto::beams;

namespace {

/// Whether the points, 2^m of them, hold one point in each cell of every
/// 2^a x 2^(m-a) grid of the unit square: a (0, m, 2)-net.
bool isNet(const std::vector<Point2f>& points, int m) {
  for (int a = 0; a <= m; ++a) {
    const int nx = 1 << a, ny = 1 << (m - a);
    std::vector<int> count(size_t(nx) * size_t(ny), 0);
    for (const Point2f& p : points) {
      const int x = std::min(int(p.x * float(nx)), nx - 1), y = std::min(int(p.y * float(ny)), ny - 1);
      if (++count[size_t(y) * size_t(nx) + size_t(x)] > 1) return false;
    }
  }
  return true;
}

}  // namespace

TEST(StratifiedEmission, EveryPrefixOfAPowerOfTwoPhotonsSpreadsEvenly) {
  for (uint64_t seed : {1ull, 77ull, 0x1234abcdull}) {
    for (int m : {4, 8, 10}) {
      const int n = 1 << m;
      std::vector<Point2f> direction;
      std::vector<std::vector<float>> numbers(5);
      for (int i = 0; i < n; ++i) {
        const EmissionSample e = stratifiedEmission(seed, uint64_t(i));
        direction.push_back(e.direction);
        const float v[5] = {e.direction.x, e.direction.y, e.position.x, e.position.y, e.pick};
        for (int k = 0; k < 5; ++k) numbers[size_t(k)].push_back(v[k]);
      }
      EXPECT_TRUE(isNet(direction, m)) << "seed " << seed << ", 2^" << m << " photons";
      // Each number alone: one photon in every 1/n.
      for (int k = 0; k < 5; ++k) {
        std::vector<int> count(size_t(n), 0);
        for (float x : numbers[size_t(k)]) ++count[size_t(std::min(int(x * float(n)), n - 1))];
        EXPECT_EQ(*std::max_element(count.begin(), count.end()), 1) << "number " << k << ", 2^" << m << " photons";
      }
      // Any two: at most 4 photons in a cell of the 2^(m/2) x 2^(m/2) grid
      // (a (t, 2)-sequence with t <= 2; n / cells = 1 on average).
      if (m % 2 != 0) continue;
      const int side = 1 << (m / 2);
      for (int j = 0; j < 5; ++j)
        for (int k = j + 1; k < 5; ++k) {
          std::vector<int> count(size_t(side) * size_t(side), 0);
          for (int i = 0; i < n; ++i) {
            const int x = std::min(int(numbers[size_t(j)][size_t(i)] * float(side)), side - 1);
            const int y = std::min(int(numbers[size_t(k)][size_t(i)] * float(side)), side - 1);
            ++count[size_t(y) * size_t(side) + size_t(x)];
          }
          EXPECT_LE(*std::max_element(count.begin(), count.end()), 4)
              << "numbers " << j << " and " << k << ", 2^" << m << " photons, seed " << seed;
        }
    }
  }
}

TEST(StratifiedEmission, OnePhotonsNumbersAreUniformAndUncorrelatedOverPasses) {
  // Photon 5 over 20000 pass seeds: each of its five numbers has mean 1/2 and
  // variance 1/12, and no two are correlated (a fixed point under
  // independent random scrambles). Tolerances: 5 standard errors.
  constexpr int Passes = 20000;
  std::vector<std::vector<double>> u(5);
  for (int s = 0; s < Passes; ++s) {
    const EmissionSample e = stratifiedEmission(mixSeed(uint64_t(s), 99), 5);
    const double v[5] = {e.pick, e.position.x, e.position.y, e.direction.x, e.direction.y};
    for (int k = 0; k < 5; ++k) u[size_t(k)].push_back(v[k]);
  }
  const double meanSe = std::sqrt(1.0 / 12.0 / Passes);
  for (int k = 0; k < 5; ++k) {
    double mean = 0.0, square = 0.0;
    for (double x : u[size_t(k)]) mean += x, square += x * x;
    mean /= Passes, square /= Passes;
    EXPECT_NEAR(mean, 0.5, 5 * meanSe) << "number " << k;
    // E[x^2] = 1/3 for a uniform; its standard error is sqrt(4/45) / sqrt(n).
    EXPECT_NEAR(square, 1.0 / 3.0, 5 * std::sqrt(4.0 / 45.0 / Passes)) << "number " << k;
    for (int j = 0; j < k; ++j) {
      double product = 0.0;
      for (int s = 0; s < Passes; ++s) product += (u[size_t(k)][size_t(s)] - 0.5) * (u[size_t(j)][size_t(s)] - 0.5);
      // Covariance of independent uniforms: 0, standard error 1/12 / sqrt(n).
      EXPECT_NEAR(product / Passes, 0.0, 5 * (1.0 / 12.0) / std::sqrt(double(Passes))) << "numbers " << j << ", " << k;
    }
  }
}

TEST(StratifiedEmission, PassesScrambleDifferently) {
  int same = 0;
  for (uint64_t i = 0; i < 64; ++i) {
    const EmissionSample a = stratifiedEmission(1, i), b = stratifiedEmission(2, i);
    same += a.direction.x == b.direction.x && a.direction.y == b.direction.y;
  }
  EXPECT_EQ(same, 0);
}

TEST(StratifiedEmission, SobolsFirstDimensionsAreVanDerCorputAndSobol2) {
  // sample_sequences.h builds the Sobol table from Joe and Kuo's rows; its
  // first two dimensions must be the (0,2)-sequence the samplers use.
  for (uint32_t i : {0u, 1u, 2u, 3u, 5u, 1000u, 123456789u, 0xffffffffu}) {
    EXPECT_EQ(sequence::sobol(0, i), sequence::vanDerCorput(i)) << i;
    EXPECT_EQ(sequence::sobol(1, i), sequence::sobol2(i)) << i;
  }
}
