#include <femto/math/ellipse_arc.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>

namespace femto {
namespace {

constexpr double TwoPi = 2.0 * 3.14159265358979323846;
// 4-point Gauss-Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun, table 25.4).
constexpr double Nodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
constexpr double Weights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
/// Relative spread of |U|, |V| and U.V under which the ellipse counts as a circle.
constexpr double CircleTolerance = 1e-7;

}  // namespace

EllipseArc::EllipseArc(const Vec3d& u, const Vec3d& v) : u_(u), v_(v) {
  const double uu = dot(u, u), vv = dot(v, v), uv = dot(u, v);
  if (!(squaredLength(cross(u, v)) > 1e-24 * uu * vv)) throw Error("EllipseArc: the two axes are parallel");
  // Speed^2 = uu sin^2 + vv cos^2 - 2 uv sin cos: constant iff uu = vv and uv = 0.
  circle_ = std::abs(uu - vv) <= CircleTolerance * (uu + vv) && std::abs(uv) <= CircleTolerance * (uu + vv);
  if (circle_) {
    perimeter_ = TwoPi * std::sqrt(0.5 * (uu + vv));
    return;
  }
  cumulative_.resize(Intervals + 1);
  cumulative_[0] = 0.0;
  const double step = TwoPi / Intervals;
  for (int i = 0; i < Intervals; ++i) cumulative_[i + 1] = cumulative_[i] + arcLength(i * step, (i + 1) * step);
  perimeter_ = cumulative_.back();
}

double EllipseArc::speed(double phi) const {
  return length(v_ * std::cos(phi) - u_ * std::sin(phi));
}

double EllipseArc::arcLength(double a, double b) const {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += Weights[k] * speed(mid + half * Nodes[k]);
  return sum * half;
}

double EllipseArc::angleAtFraction(double fraction) const {
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (circle_) return std::min(TwoPi * fraction, std::nextafter(TwoPi, 0.0));
  const double target = fraction * perimeter_;
  const auto upper = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
  const int i = std::clamp(int(upper - cumulative_.begin()) - 1, 0, Intervals - 1);
  const double step = TwoPi / Intervals;
  double lo = i * step, hi = (i + 1) * step;
  const double inInterval = target - cumulative_[i];
  // Start from the linear guess; Newton steps that leave the bracket bisect instead.
  const double span = cumulative_[i + 1] - cumulative_[i];
  double phi = lo + step * (span > 0.0 ? inInterval / span : 0.5);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double error = arcLength(i * step, phi) - inInterval;
    if (std::abs(error) <= 1e-13 * perimeter_) break;
    (error > 0.0 ? hi : lo) = phi;
    const double next = phi - error / speed(phi);
    phi = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return std::min(phi, std::nextafter(TwoPi, 0.0));
}

}  // namespace femto
