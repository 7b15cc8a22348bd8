#include <femto/time/time_deposit.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>

namespace femto {
namespace {

constexpr double GaussianCutoff = 4.0;  // truncation, in standard deviations (as Mitsuba's pixel gaussian)

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double normalPdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * 3.14159265358979323846); }
/// Antiderivative of the standard normal CDF: d/dz [z Phi(z) + phi(z)] = Phi(z).
double normalCdfIntegral(double z) { return z * normalCdf(z) + normalPdf(z); }
/// Its antiderivative: d/dz [((z^2 + 1) Phi(z) + z phi(z)) / 2] = z Phi(z) + phi(z).
double normalCdfIntegral2(double z) { return 0.5 * ((z * z + 1.0) * normalCdf(z) + z * normalPdf(z)); }

/// Fill `out` from the CDF `G` (in bin units) of the deposited density.
/// Bins outside [uLo - r, uHi + r] get nothing, and G is exactly 0 / 1 at
/// the ends of that range, so only the bins that can receive a share are visited.
template <typename Cdf>
void fillShares(double uLo, double uHi, double radius, int bins, const Cdf& G, BinShares& out) {
  out.weights.clear();
  out.first = 0;
  out.stepFrom = -1;
  out.before = G(0.0);
  out.after = 1.0 - G(double(bins));
  double lo = std::max(0.0, std::floor(uLo - radius));
  double hi = std::min(double(bins - 1), std::floor(uHi + radius));
  if (!(lo <= hi)) return;
  out.first = int(lo);
  double prev = G(lo);
  for (int i = int(lo); i <= int(hi); ++i) {
    double next = G(double(i + 1));
    out.weights.push_back(next - prev);
    prev = next;
  }
}

/// fillShares for the box filter and a box [u0, u0 + L] (L > 0): the same
/// shares, G(a) = clamp((a - u0) / L, 0, 1) (boxesCdf with radius 0), without
/// its calls per bin. Most deposits are of this kind (photon-beam pairs,
/// surface photons' time kernel), and the render spends ~10 % of its time
/// here.
void fillBoxShares(double u0, double L, int bins, BinShares& out) {
  auto G = [u0, L](double a) {
    const double x = a - u0;
    return x >= L ? 1.0 : (x <= 0.0 ? 0.0 : std::min(x / L, 1.0));
  };
  out.weights.clear();
  out.first = 0;
  out.stepFrom = -1;
  out.before = G(0.0);
  out.after = 1.0 - G(double(bins));
  const double lo = std::max(0.0, std::floor(u0)), hi = std::min(double(bins - 1), std::floor(u0 + L));
  if (!(lo <= hi)) return;
  out.first = int(lo);
  const int n = int(hi) - int(lo) + 1;
  out.weights.resize(size_t(n));
  double prev = G(lo);
  for (int k = 0; k < n; ++k) {
    const double next = G(lo + double(k + 1));
    out.weights[size_t(k)] = next - prev;
    prev = next;
  }
}

/// CDF at `a` (bins) of: uniform on [u0, u0 + L], convolved with uniform on
/// [0, w], convolved with the kernel of `f` (L and/or w may be 0: a point, one
/// box). Differences of K, K1, K2 (see the header).
double boxesCdf(const TimeFilter& f, double u0, double L, double w, double a) {
  const double r = f.radius(), x = a - u0;
  // Exact 0 / 1 outside the support. A point (box filter) on a bin's left
  // edge belongs to that bin: there G is still 0 (K(0) = 0).
  if (L == 0.0 && w == 0.0) return x > r ? 1.0 : (x <= -r ? 0.0 : f.cdf(x));
  if (x >= L + w + r) return 1.0;
  if (x <= -r) return 0.0;
  double g;
  if (L == 0.0 || w == 0.0)
    g = (f.cdfIntegral(x) - f.cdfIntegral(x - (L + w))) / (L + w);
  else
    g = (f.cdfIntegral2(x) - f.cdfIntegral2(x - L) - f.cdfIntegral2(x - w) + f.cdfIntegral2(x - L - w)) / (L * w);
  return std::clamp(g, 0.0, 1.0);
}

/// A box much shorter than the scale of the deposit becomes a point at its
/// midpoint: the differences above divide rounding noise of size eps * scale^n
/// by the lengths, while the midpoint rule errs only by O(length^2). The
/// thresholds keep both below ~1e-9 (a single box: as TimeDeposit::interval).
void collapseShortBoxes(double& u0, double& L, double& w, double r) {
  const double scale = std::max(1.0, L + w + r);
  if (L > 0.0 && w > 0.0) {
    if (L < 1e-6 * scale) u0 += 0.5 * L, L = 0.0;
    if (w < 1e-6 * scale) u0 += 0.5 * w, w = 0.0;
  }
  if (L + w < 1e-9 * std::max(1.0, r)) u0 += 0.5 * (L + w), L = w = 0.0;
}

}  // namespace

TimeFilter TimeFilter::tent(double radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) throw Error(str("tent time filter width must be positive, got ", radius));
  return TimeFilter(Type::Tent, radius, radius);
}

TimeFilter TimeFilter::gaussian(double sigma) {
  if (!(sigma > 0.0) || !std::isfinite(sigma))
    throw Error(str("gaussian time filter width must be positive, got ", sigma));
  return TimeFilter(Type::Gaussian, sigma, GaussianCutoff * sigma);
}

const char* TimeFilter::name() const {
  switch (type_) {
    case Type::Box: return "box";
    case Type::Tent: return "tent";
    case Type::Gaussian: return "gaussian";
  }
  return "?";
}

double TimeFilter::cdf(double x) const {
  if (type_ == Type::Box) return x > 0.0 ? 1.0 : 0.0;
  if (x <= -radius_) return 0.0;
  if (x >= radius_) return 1.0;
  if (type_ == Type::Tent) {
    double w = width_;
    return x <= 0.0 ? (x + w) * (x + w) / (2 * w * w) : 1.0 - (w - x) * (w - x) / (2 * w * w);
  }
  // Truncated gaussian: (Phi(x/s) - Phi(-c)) / (Phi(c) - Phi(-c)).
  double tail = normalCdf(-GaussianCutoff);
  return (normalCdf(x / width_) - tail) / (1.0 - 2.0 * tail);
}

double TimeFilter::cdfIntegral(double x) const {
  if (x <= -radius_) return 0.0;
  if (x >= radius_) return x;  // symmetric kernel: integral of K over [-r, r] is r
  if (type_ == Type::Tent) {
    // Integrals of the two quadratic pieces of the tent's CDF.
    double w = width_;
    return x <= 0.0 ? (x + w) * (x + w) * (x + w) / (6 * w * w) : x + (w - x) * (w - x) * (w - x) / (6 * w * w);
  }
  // Box has radius 0 and never gets here. Truncated gaussian: integrate
  // (Phi(s/sigma) - Phi(-c)) / Z from -r to x with the antiderivative above.
  double s = width_, tail = normalCdf(-GaussianCutoff);
  double integral = s * (normalCdfIntegral(x / s) - normalCdfIntegral(-GaussianCutoff)) - tail * (x + radius_);
  return integral / (1.0 - 2.0 * tail);
}

double TimeFilter::cdfIntegral2(double x) const {
  if (x <= -radius_) return 0.0;
  if (type_ == Type::Box) return 0.5 * x * x;  // radius 0: here x > 0
  // Beyond the support K1(s) = s: K2 grows by (x^2 - r^2) / 2 from its value at r.
  const double beyond = x > radius_ ? 0.5 * (x * x - radius_ * radius_) : 0.0;
  x = std::min(x, radius_);
  if (type_ == Type::Tent) {
    // Integrals of the two cubic pieces of K1 (K2(0) = w^2 / 24).
    double w = width_;
    return beyond + (x <= 0.0 ? std::pow(x + w, 4) / (24 * w * w)
                              : 0.5 * x * x + w * w / 12 - std::pow(w - x, 4) / (24 * w * w));
  }
  // Truncated gaussian: integrate K1 (see cdfIntegral) from -r to x.
  double s = width_, c = GaussianCutoff, tail = normalCdf(-c), y = x + radius_;
  double integral = s * s * (normalCdfIntegral2(x / s) - normalCdfIntegral2(-c)) - s * normalCdfIntegral(-c) * y -
                    0.5 * tail * y * y;
  return beyond + integral / (1.0 - 2.0 * tail);
}

void TimeDeposit::point(double opl, BinShares& out) const {
  const double u = toBins(opl);
  fillShares(u, u, filter_.radius(), grid_.bins, [&](double a) { return boxesCdf(filter_, u, 0.0, 0.0, a); }, out);
}

void TimeDeposit::interval(double opl0, double opl1, BinShares& out) const {
  double u0 = toBins(std::min(opl0, opl1)), L = toBins(std::max(opl0, opl1)) - u0, w = 0.0;
  collapseShortBoxes(u0, L, w, filter_.radius());  // below ~1e-9 bins: a point at the midpoint
  if (filter_.type() == TimeFilter::Type::Box && L > 0.0) return fillBoxShares(u0, L, grid_.bins, out);
  fillShares(u0, u0 + L, filter_.radius(), grid_.bins, [&](double a) { return boxesCdf(filter_, u0, L, 0.0, a); }, out);
}

void TimeDeposit::pulsed(double opl0, double opl1, const EmissionPulse& pulse, BinShares& out) const {
  const double lo = std::min(opl0, opl1) + pulse.offset(), hi = std::max(opl0, opl1) + pulse.offset();
  switch (pulse.type()) {
    case EmissionPulse::Type::Delta:
      return lo == hi ? point(lo, out) : interval(lo, hi, out);
    case EmissionPulse::Type::Gaussian: {
      // The pulse is the kernel: the film's box filter adds no spreading.
      if (filter_.type() != TimeFilter::Type::Box)
        throw Error(str("a gaussian emission pulse needs the transient film's time_filter \"box\", not \"",
                        filter_.name(), "\" (the pulse already smooths in time)"));
      TimeDeposit byPulse(grid_, TimeFilter::gaussian(pulse.width() / grid_.binWidth));
      return lo == hi ? byPulse.point(lo, out) : byPulse.interval(lo, hi, out);
    }
    case EmissionPulse::Type::Box:
    case EmissionPulse::Type::Continuous: break;
  }
  const double r = filter_.radius();
  double u0 = toBins(lo), L = (hi - lo) / grid_.binWidth;
  double w = pulse.type() == EmissionPulse::Type::Box ? pulse.width() / grid_.binWidth : 0.0;
  collapseShortBoxes(u0, L, w, r);
  if (pulse.type() == EmissionPulse::Type::Box) {
    fillShares(u0, u0 + L + w, r, grid_.bins, [&](double a) { return boxesCdf(filter_, u0, L, w, a); }, out);
    return;
  }
  // Continuous (a step at u0): bin i holds the running integral averaged over
  // the bin, i.e. the CDF at i + 1 of the contribution convolved with [0, 1].
  out.weights.clear();
  out.before = boxesCdf(filter_, u0, L, 0.0, 0.0);
  out.after = 1.0 - boxesCdf(filter_, u0, L, 0.0, double(grid_.bins));
  const double firstPartial = std::floor(u0 - r), lastPartial = std::floor(u0 + L + r);
  const double first = std::max(0.0, firstPartial), last = std::min(double(grid_.bins - 1), lastPartial);
  out.first = first <= last ? int(first) : 0;
  for (double i = first; i <= last; ++i) out.weights.push_back(boxesCdf(filter_, u0, L, 1.0, i + 1.0));
  out.stepFrom = lastPartial + 1.0 < double(grid_.bins) ? int(std::max(0.0, lastPartial + 1.0)) : -1;
}

}  // namespace femto
