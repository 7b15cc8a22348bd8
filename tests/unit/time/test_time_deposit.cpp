// Exact time deposition: bin shares of points and intervals under the box,
// tent and gaussian temporal filters, against hand-computed values and
// against numerical integration of the kernel (independent of the closed forms).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numeric>
#include <vector>

#include <femto/math/pcg32.h>
#include <femto/time/time_deposit.h>

namespace femto {
namespace {

TimeGrid grid(double start, double width, int bins) {
  TimeGrid g;
  g.start = start, g.binWidth = width, g.bins = bins;
  return g;
}

/// Share of bin `i` (0 when not listed).
double share(const BinShares& s, int i) {
  int k = i - s.first;
  return k >= 0 && k < int(s.weights.size()) ? s.weights[size_t(k)] : 0.0;
}

double total(const BinShares& s) { return std::accumulate(s.weights.begin(), s.weights.end(), s.before + s.after); }

/// Kernel density in bins, written directly (not from the CDFs under test).
double kernelPdf(const TimeFilter& f, double x) {
  if (f.type() == TimeFilter::Type::Tent) return std::max(0.0, f.width() - std::abs(x)) / (f.width() * f.width());
  double s = f.width();
  if (std::abs(x) > 4 * s) return 0.0;
  double z = std::erf(4.0 / std::sqrt(2.0));  // mass inside +-4 sigma
  return std::exp(-0.5 * x * x / (s * s)) / (s * std::sqrt(2 * M_PI)) / z;
}

/// Composite Simpson rule on [a, b] with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  double h = (b - a) / n, sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4 : 2);
  return sum * h / 3;
}

TEST(TimeDeposit, BoxPointLandsInItsBinAsTimeGridBinOf) {
  TimeGrid g = grid(2.0, 0.5, 8);  // window [2, 6)
  TimeDeposit d(g, TimeFilter::box());
  BinShares s;
  for (double opl : {2.0, 2.49, 2.5, 3.0, 5.999, 4.25}) {
    d.point(opl, s);
    ASSERT_EQ(s.weights.size(), 1u) << opl;
    EXPECT_EQ(s.first, g.binOf(opl)) << opl;
    EXPECT_EQ(s.weights[0], 1.0);
    EXPECT_EQ(s.before + s.after, 0.0);
  }
  d.point(1.999, s);
  EXPECT_TRUE(s.weights.empty());
  EXPECT_EQ(s.before, 1.0);
  d.point(6.0, s);  // the window is half-open: its end belongs to "after"
  EXPECT_TRUE(s.weights.empty());
  EXPECT_EQ(s.after, 1.0);
}

TEST(TimeDeposit, BoxIntervalGetsExactOverlapFractions) {
  TimeDeposit d(grid(0.0, 1.0, 10), TimeFilter::box());
  BinShares s;
  d.interval(1.5, 3.5, s);  // half of bin 1, all of bin 2, half of bin 3
  EXPECT_DOUBLE_EQ(share(s, 1), 0.25);
  EXPECT_DOUBLE_EQ(share(s, 2), 0.5);
  EXPECT_DOUBLE_EQ(share(s, 3), 0.25);
  EXPECT_DOUBLE_EQ(total(s), 1.0);
  d.interval(3.5, 1.5, s);  // reversed ends: the same interval
  EXPECT_DOUBLE_EQ(share(s, 2), 0.5);
  d.interval(-1.0, 1.0, s);  // half before the window
  EXPECT_DOUBLE_EQ(s.before, 0.5);
  EXPECT_DOUBLE_EQ(share(s, 0), 0.5);
  d.interval(9.0, 13.0, s);  // three quarters after it
  EXPECT_DOUBLE_EQ(s.after, 0.75);
  EXPECT_DOUBLE_EQ(share(s, 9), 0.25);
}

TEST(TimeDeposit, TentPointMatchesHandComputedShares) {
  TimeDeposit d(grid(0.0, 1.0, 10), TimeFilter::tent(1.0));
  BinShares s;
  // Kernel 1 - |x - 2.25| on [1.25, 3.25]; its integrals over [1,2), [2,3), [3,4):
  d.point(2.25, s);
  EXPECT_NEAR(share(s, 1), 0.28125, 1e-15);
  EXPECT_NEAR(share(s, 2), 0.6875, 1e-15);
  EXPECT_NEAR(share(s, 3), 0.03125, 1e-15);
  EXPECT_NEAR(total(s), 1.0, 1e-15);
  // Bin width 2: the same in OPL units scaled by 2 (kernel width is in bins).
  TimeDeposit wide(grid(0.0, 2.0, 10), TimeFilter::tent(1.0));
  wide.point(4.5, s);
  EXPECT_NEAR(share(s, 2), 0.6875, 1e-15);
}

TEST(TimeDeposit, SampleNearTheWindowEdgeLosesExactlyTheOutsideShare) {
  TimeDeposit d(grid(0.0, 1.0, 4), TimeFilter::tent(1.0));
  BinShares s;
  d.point(0.25, s);  // kernel on [-0.75, 1.25]: mass below 0 is (1 - 0.25)^2 / 2
  EXPECT_NEAR(s.before, 0.28125, 1e-15);
  EXPECT_NEAR(total(s) - s.before, 0.71875, 1e-15);
  d.point(3.9, s);  // kernel on [2.9, 4.9]: mass above 4 is (1 - 0.1)^2 / 2
  EXPECT_NEAR(s.after, 0.405, 1e-15);
  EXPECT_NEAR(total(s) - s.after, 0.595, 1e-15);
  // Gaussian: the mass outside is the normal tail, renormalised to +-4 sigma.
  TimeDeposit g(grid(0.0, 1.0, 4), TimeFilter::gaussian(0.5));
  g.point(0.5, s);  // one sigma from the window start
  double tail = 0.5 * std::erfc(1.0 / std::sqrt(2.0)), cut = 0.5 * std::erfc(4.0 / std::sqrt(2.0));
  EXPECT_NEAR(s.before, (tail - cut) / (1 - 2 * cut), 1e-12);
}

TEST(TimeDeposit, PointSharesAreTheKernelIntegratedOverEachBin) {
  PCG32 rng(3, 1);
  for (TimeFilter f : {TimeFilter::tent(1.0), TimeFilter::tent(2.7), TimeFilter::gaussian(0.5), TimeFilter::gaussian(1.3)}) {
    TimeDeposit d(grid(-1.0, 0.25, 40), f);
    BinShares s;
    for (int trial = 0; trial < 20; ++trial) {
      double opl = -1.0 + 10.0 * rng.nextFloat();  // inside and near both edges
      d.point(opl, s);
      double u = (opl + 1.0) / 0.25;
      EXPECT_NEAR(total(s), 1.0, 1e-12) << f.name() << " at " << opl;
      for (int i = 0; i < 40; ++i) {
        double expected = simpson([&](double x) { return kernelPdf(f, x - u); }, i, i + 1, 2000);
        EXPECT_NEAR(share(s, i), expected, 1e-7) << f.name() << " width " << f.width() << " at " << opl << " bin " << i;
      }
    }
  }
}

TEST(TimeDeposit, IntervalSharesAreTheAverageOfPointShares) {
  // The closed forms (integrals of the CDF) against the average over the
  // interval of point deposits (numerically integrated).
  PCG32 rng(5, 1);
  for (TimeFilter f : {TimeFilter::box(), TimeFilter::tent(1.0), TimeFilter::tent(3.0), TimeFilter::gaussian(0.7)}) {
    TimeDeposit d(grid(0.0, 1.0, 16), f);
    BinShares s, p;
    for (int trial = 0; trial < 10; ++trial) {
      double a = -2.0 + 19.0 * rng.nextFloat(), len = 0.01 + 6.0 * rng.nextFloat() * rng.nextFloat();
      d.interval(a, a + len, s);
      EXPECT_NEAR(total(s), 1.0, 1e-12);
      // Simpson over t of all bins' point shares at once.
      const int n = 4000;
      std::vector<double> expected(16, 0.0);
      for (int j = 0; j <= n; ++j) {
        d.point(a + len * j / n, p);
        double w = (j == 0 || j == n ? 1.0 : (j % 2 ? 4.0 : 2.0)) / (3.0 * n);
        for (int i = 0; i < 16; ++i) expected[size_t(i)] += w * share(p, i);
      }
      for (int i = 0; i < 16; ++i) {
        // The box's point share jumps at bin edges, where Simpson is not
        // accurate: there the exact overlap fraction is the reference.
        double ref = f.type() == TimeFilter::Type::Box
                         ? std::max(0.0, std::min(a + len, i + 1.0) - std::max(a, double(i))) / len
                         : expected[size_t(i)];
        EXPECT_NEAR(share(s, i), ref, f.type() == TimeFilter::Type::Box ? 1e-12 : 1e-7)
            << f.name() << " [" << a << ", " << a + len << "] bin " << i;
      }
    }
  }
}

TEST(TimeDeposit, IntervalsInsideTheWindowDepositTheirWholeValue) {
  PCG32 rng(9, 1);
  TimeDeposit d(grid(0.0, 1.0, 100), TimeFilter::gaussian(1.0));
  BinShares s;
  for (int trial = 0; trial < 100; ++trial) {
    double a = 10 + 70 * rng.nextFloat(), len = 10 * rng.nextFloat();
    d.interval(a, a + len, s);
    EXPECT_EQ(s.before, 0.0);
    EXPECT_EQ(s.after, 0.0);
    EXPECT_NEAR(std::accumulate(s.weights.begin(), s.weights.end(), 0.0), 1.0, 1e-12);
  }
}

TEST(TimeDeposit, DegenerateAndFarAwayIntervalsStayFinite) {
  for (TimeFilter f : {TimeFilter::box(), TimeFilter::tent(1.5), TimeFilter::gaussian(0.5)}) {
    TimeDeposit d(grid(0.0, 1.0, 8), f);
    BinShares point, s;
    d.point(3.3, point);
    d.interval(3.3, 3.3, s);  // zero length: a point
    EXPECT_EQ(s.weights, point.weights) << f.name();
    d.interval(3.3, 3.3 + 1e-13, s);  // tiny: no division of rounding noise
    for (double w : s.weights) EXPECT_TRUE(std::isfinite(w));
    EXPECT_NEAR(total(s), 1.0, 1e-12);
    EXPECT_NEAR(share(s, 3), share(point, 3), 1e-9);
    d.interval(3.3, 3.3 + 1e-7, s);  // short but above the point threshold: still accurate
    EXPECT_NEAR(share(s, 3), share(point, 3), 1e-6) << f.name();
    d.interval(1e30, 2e30, s);
    EXPECT_TRUE(s.weights.empty());
    EXPECT_EQ(s.after, 1.0);
    d.point(-1e30, s);
    EXPECT_TRUE(s.weights.empty());
    EXPECT_EQ(s.before, 1.0);
  }
}

TEST(TimeDeposit, HorizonIsTheWindowEndPlusTheKernelReach) {
  EXPECT_EQ(TimeDeposit(grid(1.0, 0.5, 4), TimeFilter::box()).horizon(), 3.0);
  EXPECT_EQ(TimeDeposit(grid(1.0, 0.5, 4), TimeFilter::tent(2.0)).horizon(), 4.0);
  EXPECT_EQ(TimeDeposit(grid(1.0, 0.5, 4), TimeFilter::gaussian(0.5)).horizon(), 4.0);
}

}  // namespace
}  // namespace femto
