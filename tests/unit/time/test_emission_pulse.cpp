// Emitter pulses: parsing and its errors, sampling emission times, and the
// exact deposit of pulsed contributions (TimeDeposit::pulsed) against
// numerical integration of the pulse convolved with the film's kernel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <vector>

#include <femto/base/error.h>
#include <femto/core/properties.h>
#include <femto/math/pcg32.h>
#include <femto/time/emission_pulse.h>
#include <femto/time/time_deposit.h>

#include "plugin_util.h"

namespace femto {
namespace {

using test::errorMessageOf;

Properties emitterProps(const std::string& pulse) {
  Properties props("point");
  if (!pulse.empty()) props.setString("pulse", pulse);
  return props;
}

void expectContains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "\"" << part << "\" not in: " << message;
}

TEST(EmissionPulse, DefaultIsADiracAtZero) {
  EmissionPulse pulse = EmissionPulse::fromProperties(emitterProps(""));
  EXPECT_TRUE(pulse.isDelta());
  EXPECT_EQ(pulse.offset(), 0.0);
  EXPECT_EQ(pulse.earliest(), 0.0);
  EXPECT_EQ(pulse.sampleOffset(0.7), 0.0);
}

TEST(EmissionPulse, ParsesEveryShapeInOplAndSeconds) {
  Properties g = emitterProps("gaussian");
  g.setFloat("pulse_fwhm", 2.0);
  g.setFloat("pulse_offset", 5.0);
  EmissionPulse gauss = EmissionPulse::fromProperties(g);
  EXPECT_EQ(gauss.type(), EmissionPulse::Type::Gaussian);
  EXPECT_NEAR(gauss.width(), 2.0 / (2.0 * std::sqrt(2.0 * std::log(2.0))), 1e-6);  // sigma = FWHM / 2.3548
  EXPECT_NEAR(gauss.earliest(), 5.0 - 4.0 * gauss.width(), 1e-6);
  EXPECT_NEAR(gauss.latest(), 5.0 + 4.0 * gauss.width(), 1e-6);

  Properties b = emitterProps("box");
  b.setFloat("pulse_width_time", 1e-9);  // 1 ns = 0.2998 m
  EmissionPulse box = EmissionPulse::fromProperties(b);
  EXPECT_NEAR(box.width(), 0.299792458, 1e-7);
  EXPECT_EQ(box.earliest(), 0.0);
  EXPECT_NEAR(box.latest(), 0.299792458, 1e-7);

  Properties c = emitterProps("continuous");
  c.setFloat("pulse_offset", -1.5);
  EmissionPulse step = EmissionPulse::fromProperties(c);
  EXPECT_TRUE(step.isContinuous());
  EXPECT_EQ(step.earliest(), -1.5);
  EXPECT_TRUE(std::isinf(step.latest()));

  Properties s = emitterProps("gaussian");
  s.setFloat("pulse_sigma", 0.25);
  EXPECT_EQ(EmissionPulse::fromProperties(s), EmissionPulse::gaussian(0.25));
}

TEST(EmissionPulse, BadParametersAreClearErrors) {
  std::string m = errorMessageOf([] { EmissionPulse::fromProperties(emitterProps("gausian")); });
  expectContains(m, "unknown pulse \"gausian\"");
  expectContains(m, "did you mean \"gaussian\"");
  m = errorMessageOf([] {
    Properties p = emitterProps("box");
    p.setFloat("pulse_width", -1.0);
    EmissionPulse::fromProperties(p);
  });
  expectContains(m, "pulse_width");
  expectContains(m, "must be positive");
  m = errorMessageOf([] {
    Properties p = emitterProps("gaussian");
    p.setFloat("pulse_fwhm", 1.0);
    p.setFloat("pulse_sigma", 1.0);
    EmissionPulse::fromProperties(p);
  });
  expectContains(m, "not both");
  m = errorMessageOf([] { EmissionPulse::fromProperties(emitterProps("gaussian")); });
  expectContains(m, "pulse_sigma");
  m = errorMessageOf([] { EmissionPulse::fromProperties(emitterProps("box")); });
  expectContains(m, "missing parameter \"pulse_width\"");
  m = errorMessageOf([] {
    Properties p = emitterProps("");
    p.setFloat("pulse_width", 1.0);  // a box parameter on the default delta pulse
    EmissionPulse::fromProperties(p);
  });
  expectContains(m, "only applies to pulse \"box\"");
  m = errorMessageOf([] {
    Properties p = emitterProps("box");
    p.setFloat("pulse_width", 1.0);
    p.setFloat("pulse_width_time", 1.0);
    EmissionPulse::fromProperties(p);
  });
  expectContains(m, "not both");
  m = errorMessageOf([] { EmissionPulse::continuous().sampleOffset(0.5); });
  expectContains(m, "cannot be sampled");
}

TEST(EmissionPulse, SampledOffsetsAreDistributedAsThePulse) {
  // Inversion: the sample at u is the u-quantile, so the CDF at it is u.
  EmissionPulse gauss = EmissionPulse::gaussian(0.5, 2.0);
  const double tail = 0.5 * std::erfc(4.0 / std::sqrt(2.0));
  for (double u : {0.0, 1e-6, 0.1, 0.5, 0.77, 0.999999}) {
    double t = gauss.sampleOffset(u);
    double cdf = (0.5 * std::erfc(-(t - 2.0) / 0.5 / std::sqrt(2.0)) - tail) / (1.0 - 2.0 * tail);
    EXPECT_NEAR(cdf, u, 1e-12) << u;
  }
  EXPECT_NEAR(gauss.sampleOffset(0.0), gauss.earliest(), 1e-9);
  EmissionPulse box = EmissionPulse::box(3.0, 1.0);
  EXPECT_EQ(box.sampleOffset(0.0), 1.0);
  EXPECT_EQ(box.sampleOffset(0.5), 2.5);
  EXPECT_EQ(EmissionPulse::delta(4.0).sampleOffset(0.3), 4.0);
}

// ---- Deposit math -----------------------------------------------------------

TimeGrid grid(double start, double width, int bins) {
  TimeGrid g;
  g.start = start, g.binWidth = width, g.bins = bins;
  return g;
}

double share(const BinShares& s, int i) {
  int k = i - s.first;
  double w = k >= 0 && k < int(s.weights.size()) ? s.weights[size_t(k)] : 0.0;
  return s.stepFrom >= 0 && i >= s.stepFrom ? 1.0 : w;
}

double total(const BinShares& s) { return std::accumulate(s.weights.begin(), s.weights.end(), s.before + s.after); }

/// Densities written directly (not from the CDFs under test), in OPL.
double pulseDensity(const EmissionPulse& p, double t) {
  double x = t - p.offset();
  if (p.type() == EmissionPulse::Type::Box) return x >= 0.0 && x <= p.width() ? 1.0 / p.width() : 0.0;
  double s = p.width();
  if (std::abs(x) > 4 * s) return 0.0;
  return std::exp(-0.5 * x * x / (s * s)) / (s * std::sqrt(2 * M_PI)) / std::erf(4.0 / std::sqrt(2.0));
}

double filterDensity(const TimeFilter& f, double x) {  // in bins
  return std::max(0.0, f.width() - std::abs(x)) / (f.width() * f.width());  // tent
}

/// Composite Simpson rule on [a, b] with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
  double h = (b - a) / n, sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4 : 2);
  return sum * h / 3;
}

/// Integral of `density` (OPL) over bin i of `g`, split at the kinks `kinks` so Simpson converges.
double binIntegral(const TimeGrid& g, int i, const std::function<double(double)>& density, std::vector<double> kinks) {
  double a = g.start + i * g.binWidth, b = a + g.binWidth;
  kinks.push_back(a), kinks.push_back(b);
  std::sort(kinks.begin(), kinks.end());
  double sum = 0.0;
  for (size_t k = 0; k + 1 < kinks.size(); ++k) {
    double lo = std::max(a, kinks[k]), hi = std::min(b, kinks[k + 1]);
    // Evaluate just inside the piece: the density jumps at its ends (box, truncation).
    double eps = 1e-12 * (hi - lo);
    if (hi > lo) sum += simpson([&](double t) { return density(std::clamp(t, lo + eps, hi - eps)); }, lo, hi, 400);
  }
  return sum;
}

TEST(EmissionPulseDeposit, GaussianAndBoxPulsesOfAPointAreThePulseIntegratedOverEachBin) {
  const TimeGrid g = grid(1.0, 0.5, 40);
  TimeDeposit d(g, TimeFilter::box());
  PCG32 rng(11, 1);
  for (EmissionPulse p : {EmissionPulse::gaussian(0.4, 1.0), EmissionPulse::gaussian(1.7, -2.0), EmissionPulse::box(0.8, 0.3),
                          EmissionPulse::box(3.3, -1.0)}) {
    BinShares s;
    for (int trial = 0; trial < 10; ++trial) {
      double tau = 12.0 * rng.nextFloat();
      d.pulsed(tau, tau, p, s);
      EXPECT_NEAR(total(s), 1.0, 1e-12) << p.toString();
      EmissionPulse shifted = p.type() == EmissionPulse::Type::Box ? EmissionPulse::box(p.width(), p.offset() + tau)
                                                                   : EmissionPulse::gaussian(p.width(), p.offset() + tau);
      std::vector<double> kinks = {shifted.earliest(), shifted.latest()};
      for (int i = 0; i < g.bins; ++i) {
        double expected = binIntegral(g, i, [&](double t) { return pulseDensity(shifted, t); }, kinks);
        EXPECT_NEAR(share(s, i), expected, 1e-9) << p.toString() << " at " << tau << " bin " << i;
      }
    }
  }
}

TEST(EmissionPulseDeposit, PulsedIntervalsAndTentFilterMatchNumericalConvolution) {
  // An interval [tau, tau + L] emitted with a box pulse through a tent
  // filter (all three convolved: the K2 closed form), and a gaussian pulse
  // over an interval with the box filter, against Simpson over the interval
  // of exact point deposits.
  PCG32 rng(13, 1);
  struct Case {
    TimeFilter filter;
    EmissionPulse pulse;
  };
  for (Case c : {Case{TimeFilter::tent(1.0), EmissionPulse::box(1.3, 0.2)}, Case{TimeFilter::tent(2.5), EmissionPulse::box(0.05)},
                 Case{TimeFilter::gaussian(0.7), EmissionPulse::box(2.0, -0.5)}, Case{TimeFilter::box(), EmissionPulse::box(1.5)},
                 Case{TimeFilter::box(), EmissionPulse::gaussian(0.6, 0.4)}}) {
    const TimeGrid g = grid(0.0, 1.0, 24);
    TimeDeposit d(g, c.filter);
    BinShares s, p;
    for (int trial = 0; trial < 6; ++trial) {
      double a = 2.0 + 14.0 * rng.nextFloat(), len = 0.02 + 5.0 * rng.nextFloat();
      d.pulsed(a, a + len, c.pulse, s);
      EXPECT_NEAR(total(s), 1.0, 1e-12);
      const int n = 4000;
      std::vector<double> expected(size_t(g.bins), 0.0);
      for (int j = 0; j <= n; ++j) {
        double t = a + len * j / n;
        d.pulsed(t, t, c.pulse, p);  // point deposits: checked against the pulse itself above / in test_time_deposit
        double w = (j == 0 || j == n ? 1.0 : (j % 2 ? 4.0 : 2.0)) / (3.0 * n);
        for (int i = 0; i < g.bins; ++i) expected[size_t(i)] += w * share(p, i);
      }
      // Simpson over a kinked integrand (box filter and box pulse) converges
      // as h^2: 4000 steps leave ~1e-7.
      double tolerance = c.filter.type() == TimeFilter::Type::Box && c.pulse.type() == EmissionPulse::Type::Box ? 2e-6 : 1e-7;
      for (int i = 0; i < g.bins; ++i)
        EXPECT_NEAR(share(s, i), expected[size_t(i)], tolerance)
            << c.filter.name() << " " << c.pulse.toString() << " [" << a << ", " << a + len << "] bin " << i;
    }
  }
}

TEST(EmissionPulseDeposit, BoxPulseOfAPointThroughATentIsTheConvolution) {
  const TimeGrid g = grid(0.0, 1.0, 16);
  const TimeFilter tent = TimeFilter::tent(1.5);
  TimeDeposit d(g, tent);
  EmissionPulse box = EmissionPulse::box(2.2, 0.5);
  BinShares s;
  const double tau = 4.3;
  d.pulsed(tau, tau, box, s);
  // Density of box (OPL = bins here) convolved with the tent, by Simpson.
  auto density = [&](double t) {
    return simpson([&](double e) { return filterDensity(tent, t - e) / box.width(); }, tau + 0.5, tau + 2.7, 2000);
  };
  for (int i = 0; i < g.bins; ++i) {
    double expected = simpson(density, i, i + 1, 200);
    EXPECT_NEAR(share(s, i), expected, 1e-6) << "bin " << i;
  }
}

TEST(EmissionPulseDeposit, ContinuousPulseGivesTheRunningIntegralAveragedOverEachBin) {
  // Level of bin i = integral over the bin of C(t), C the CDF of the Dirac
  // deposit: against Simpson of the point/interval CDFs, for several filters.
  PCG32 rng(17, 1);
  const TimeGrid g = grid(-2.0, 0.5, 30);
  for (TimeFilter f : {TimeFilter::box(), TimeFilter::tent(1.0), TimeFilter::gaussian(0.8)}) {
    TimeDeposit d(g, f);
    BinShares s, dirac;
    for (int trial = 0; trial < 8; ++trial) {
      double a = -3.0 + 14.0 * rng.nextFloat(), len = trial % 2 ? 0.0 : 0.5 + 2.5 * rng.nextFloat();
      if (len == 0.0 && f.type() == TimeFilter::Type::Box) continue;  // a step: exact test below
      d.pulsed(a, a + len, EmissionPulse::continuous(), s);
      d.pulsed(a, a + len, EmissionPulse::delta(), dirac);
      EXPECT_NEAR(s.before, dirac.before, 1e-12);
      EXPECT_NEAR(s.after, dirac.after, 1e-12);
      // C(t) from the Dirac deposit on a fine grid (its CDF), integrated over each coarse bin.
      // (The filter's width is in bins: 64 times more fine bins.)
      TimeFilter fineFilter = f.type() == TimeFilter::Type::Box    ? f
                              : f.type() == TimeFilter::Type::Tent ? TimeFilter::tent(64 * f.width())
                                                                   : TimeFilter::gaussian(64 * f.width());
      TimeDeposit fine(grid(-2.0, 0.5 / 64, 30 * 64), fineFilter);
      BinShares fs;
      fine.pulsed(a, a + len, EmissionPulse::delta(), fs);
      double level = fs.before;
      for (int i = 0; i < g.bins; ++i) {
        // Trapezoid rule on the fine CDF values at fine-bin edges (the CDF is
        // piecewise smooth; 64 sub-bins give ~1e-5 at kinks).
        double integral = 0.0;
        for (int k = 0; k < 64; ++k) {
          double next = level + share(fs, i * 64 + k);
          integral += 0.5 * (level + next) / 64;
          level = next;
        }
        EXPECT_NEAR(share(s, i), integral, 2e-4) << f.name() << " [" << a << ", " << a + len << "] bin " << i;
      }
      // Once everything has arrived, each bin holds the whole value.
      if (s.after == 0.0) EXPECT_EQ(share(s, g.bins - 1), 1.0);
    }
  }
}

TEST(EmissionPulseDeposit, ContinuousPulseOfAPointWithTheBoxFilterIsExact) {
  TimeDeposit d(grid(0.0, 1.0, 8), TimeFilter::box());
  BinShares s;
  d.pulsed(2.25, 2.25, EmissionPulse::continuous(1.0), s);  // switches on at 3.25
  for (int i = 0; i < 3; ++i) EXPECT_EQ(share(s, i), 0.0);
  EXPECT_DOUBLE_EQ(share(s, 3), 0.75);
  EXPECT_EQ(s.stepFrom, 4);
  for (int i = 4; i < 8; ++i) EXPECT_EQ(share(s, i), 1.0);
  EXPECT_EQ(s.before, 0.0);
  EXPECT_EQ(s.after, 0.0);
  d.pulsed(-5.0, -5.0, EmissionPulse::continuous(), s);  // on before the window: every bin full
  EXPECT_EQ(s.stepFrom, 0);
  EXPECT_EQ(s.before, 1.0);
  d.pulsed(20.0, 20.0, EmissionPulse::continuous(), s);  // after it: nothing
  EXPECT_EQ(s.stepFrom, -1);
  EXPECT_TRUE(s.weights.empty());
  EXPECT_EQ(s.after, 1.0);
}

TEST(EmissionPulseDeposit, DeltaPulseIsTheUnpulsedDepositShifted) {
  TimeDeposit d(grid(0.0, 1.0, 10), TimeFilter::tent(1.0));
  BinShares a, b;
  d.pulsed(2.0, 2.0, EmissionPulse::delta(1.25), a);
  d.point(3.25, b);
  EXPECT_EQ(a.weights, b.weights);
  EXPECT_EQ(a.first, b.first);
  d.pulsed(2.0, 4.0, EmissionPulse::delta(), a);
  d.interval(2.0, 4.0, b);
  EXPECT_EQ(a.weights, b.weights);
}

TEST(EmissionPulseDeposit, GaussianPulseNeedsTheBoxFilter) {
  TimeDeposit d(grid(0.0, 1.0, 10), TimeFilter::tent(1.0));
  BinShares s;
  std::string m = errorMessageOf([&] { d.pulsed(2.0, 2.0, EmissionPulse::gaussian(1.0), s); });
  EXPECT_NE(m.find("time_filter \"box\""), std::string::npos) << m;
}

TEST(EmissionPulseDeposit, ShortBoxesAndFarContributionsStayAccurateAndFinite) {
  for (TimeFilter f : {TimeFilter::box(), TimeFilter::tent(1.5), TimeFilter::gaussian(0.5)}) {
    TimeDeposit d(grid(0.0, 1.0, 8), f);
    BinShares s, ref;
    d.pulsed(3.3, 3.3 + 1e-12, EmissionPulse::box(1e-12), s);  // both tiny: a point
    d.point(3.3 + 1e-12, ref);
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(share(s, i), share(ref, i), 1e-9) << f.name();
    d.pulsed(3.3, 3.3 + 1e-9, EmissionPulse::box(2.0), s);  // tiny interval, long pulse: the interval [3.3, 5.3]
    d.interval(3.3 + 5e-10, 5.3 + 5e-10, ref);
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(share(s, i), share(ref, i), 1e-8) << f.name();
    EXPECT_NEAR(total(s), 1.0, 1e-12);
    d.pulsed(1e30, 2e30, EmissionPulse::box(1.0), s);
    EXPECT_TRUE(s.weights.empty());
    EXPECT_EQ(s.after, 1.0);
  }
}

}  // namespace
}  // namespace femto
