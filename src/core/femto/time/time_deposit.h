#pragma once
// Exact deposition of radiance on a transient film's time axis.
//
// A contribution reported at one OPL, or spread uniformly over an OPL
// interval (photon-beam estimates, see SEED.md), is split over the time bins
// by the *exact* share each bin receives: the integral over the bin of the
// contribution's density convolved with a temporal reconstruction kernel.
// Working in bin units u = (opl - start) / binWidth (bin i = [i, i+1)):
//
//   point at u:          share_i = K(i+1-u) - K(i-u)                       (K: kernel CDF)
//   interval [u0, u1]:   share_i = G(i+1) - G(i),
//                        G(a) = (K1(a-u0) - K1(a-u1)) / (u1-u0)           (K1(x) = integral of K up to x)
//
// G is the CDF of the box-interval-convolved-with-kernel density, so the
// shares of all bins plus the parts before and after the window telescope to
// exactly 1: nothing is lost or invented by the binning.
//
// Emitter pulses (emission_pulse.h) are one more convolution (pulsed()):
// a box pulse of width w is a second box, G(a) = second difference of K2
// (K2 = integral of K1) over the interval length and w, divided by both; a
// gaussian pulse replaces the kernel (it needs the box time filter: no closed
// form convolves it with a tent or a truncated gaussian); a continuous pulse
// (step) gives each bin the *level* of the running integral averaged over the
// bin, which is the CDF at the bin's end of the contribution convolved with a
// one-bin box.
#include <limits>
#include <vector>

#include <femto/time/emission_pulse.h>
#include <femto/time/time_grid.h>

namespace femto {

/// Temporal reconstruction kernel, in units of bins, normalised to integral 1.
class TimeFilter {
 public:
  enum class Type { Box, Tent, Gaussian };

  /// No spreading: a point lands in the bin that contains it (TimeGrid::binOf).
  static TimeFilter box() { return TimeFilter(Type::Box, 0.0, 0.0); }
  /// Triangle of half-width `radius` bins (radius 1 = linear interpolation between bin centres).
  static TimeFilter tent(double radius);
  /// Gaussian of standard deviation `sigma` bins, truncated at 4 sigma and renormalised.
  static TimeFilter gaussian(double sigma);

  Type type() const { return type_; }
  /// The width parameter (tent radius, gaussian sigma; 0 for box), in bins.
  double width() const { return width_; }
  /// Half-width of the kernel's support, in bins: K(x) = 0 for x <= -radius, 1 for x >= radius.
  double radius() const { return radius_; }
  /// K(x): integral of the kernel over (-inf, x]. For box, K(0) = 0 (a point
  /// on a bin's left edge belongs to that bin).
  double cdf(double x) const;
  /// K1(x): integral of K over (-inf, x]; equals x for x >= radius (symmetric kernels).
  double cdfIntegral(double x) const;
  /// K2(x): integral of K1 over (-inf, x]; equals (x^2 + variance) / 2 for x >= radius.
  double cdfIntegral2(double x) const;
  const char* name() const;

 private:
  TimeFilter(Type type, double width, double radius) : type_(type), width_(width), radius_(radius) {}
  Type type_;
  double width_, radius_;
};

/// Bin shares of one contribution: weights[k] is the share of bin first + k;
/// before/after are the shares falling before the window or at/after its end.
/// weights + before + after sum to 1 (up to rounding).
/// Continuous emission (a step) instead gives levels: weights[k] is the
/// running integral averaged over bin first + k, every bin >= stepFrom gets
/// the whole value (stepFrom = -1: none), `before` is the level at the window
/// start and `after` the part still to arrive at its end.
struct BinShares {
  int first = 0;
  std::vector<double> weights;
  double before = 0.0, after = 0.0;
  int stepFrom = -1;
};

class TimeDeposit {
 public:
  /// `unboundedHorizon`: horizon() is infinite, so integrators trace light past
  /// the window and the film keeps it (for a complete steady image and `after`).
  TimeDeposit(const TimeGrid& grid, const TimeFilter& filter, bool unboundedHorizon = false)
      : grid_(grid), filter_(filter), unboundedHorizon_(unboundedHorizon) {}

  /// Shares of a contribution at `opl` (finite).
  void point(double opl, BinShares& out) const;
  /// Shares of a contribution spread uniformly over [opl0, opl1] (finite, any
  /// order). Intervals shorter than ~1e-9 bins are deposited as a point at
  /// their midpoint (the closed form would divide rounding noise by the length).
  void interval(double opl0, double opl1, BinShares& out) const;
  /// Shares of a contribution over [opl0, opl1] (a point when equal) for a
  /// Dirac emission at OPL 0, emitted instead with `pulse`: the contribution
  /// convolved with the pulse (and the kernel), exactly. Throws for a
  /// gaussian pulse unless the filter is box.
  void pulsed(double opl0, double opl1, const EmissionPulse& pulse, BinShares& out) const;

  /// OPL from which nothing reaches the window (window end + kernel radius),
  /// or infinity when the film asked for an unbounded horizon. Contributions
  /// at or past it are not deposited at all (TransientSampleRecorder), so the
  /// outputs do not depend on how far an integrator traces past the window.
  double horizon() const {
    return unboundedHorizon_ ? std::numeric_limits<double>::infinity()
                             : grid_.end() + filter_.radius() * grid_.binWidth;
  }
  const TimeGrid& grid() const { return grid_; }
  const TimeFilter& filter() const { return filter_; }
  bool unboundedHorizon() const { return unboundedHorizon_; }

 private:
  double toBins(double opl) const { return (opl - grid_.start) / grid_.binWidth; }
  TimeGrid grid_;
  TimeFilter filter_;
  bool unboundedHorizon_;
};

}  // namespace femto
