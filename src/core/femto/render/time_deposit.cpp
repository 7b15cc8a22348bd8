#include <femto/render/time_deposit.h>

#include <algorithm>
#include <cmath>

#include <femto/core/error.h>

namespace femto {
namespace {

constexpr double GaussianCutoff = 4.0;  // truncation, in standard deviations (as Mitsuba's pixel gaussian)

double normalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }
double normalPdf(double z) { return std::exp(-0.5 * z * z) / std::sqrt(2.0 * 3.14159265358979323846); }
/// Antiderivative of the standard normal CDF: d/dz [z Phi(z) + phi(z)] = Phi(z).
double normalCdfIntegral(double z) { return z * normalCdf(z) + normalPdf(z); }

/// Fill `out` from the CDF `G` (in bin units) of the deposited density.
/// Bins outside [uLo - r, uHi + r] get nothing, and G is exactly 0 / 1 at
/// the ends of that range, so only the bins that can receive a share are visited.
template <typename Cdf>
void fillShares(double uLo, double uHi, double radius, int bins, const Cdf& G, BinShares& out) {
  out.weights.clear();
  out.first = 0;
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

void TimeDeposit::point(double opl, BinShares& out) const {
  double u = toBins(opl), r = filter_.radius();
  // Exact 0/1 outside the support, so far-away samples give exact zeros.
  auto G = [&](double a) {
    double x = a - u;
    return x > r ? 1.0 : (x <= -r ? 0.0 : filter_.cdf(x));
  };
  fillShares(u, u, r, grid_.bins, G, out);
}

void TimeDeposit::interval(double opl0, double opl1, BinShares& out) const {
  double u0 = toBins(std::min(opl0, opl1)), u1 = toBins(std::max(opl0, opl1));
  double length = u1 - u0, r = filter_.radius();
  // Below this length the closed form loses its digits to cancellation (its
  // numerator is a difference of values of size ~r); a point is exact to
  // within the length, far below float precision of the film.
  if (!(length > 1e-9 * std::max(1.0, r))) return point(grid_.start + 0.5 * (u0 + u1) * grid_.binWidth, out);
  auto G = [&](double a) {
    if (a - u1 >= r) return 1.0;
    if (a - u0 <= -r) return 0.0;
    return std::clamp((filter_.cdfIntegral(a - u0) - filter_.cdfIntegral(a - u1)) / length, 0.0, 1.0);
  };
  fillShares(u0, u1, r, grid_.bins, G, out);
}

}  // namespace femto
