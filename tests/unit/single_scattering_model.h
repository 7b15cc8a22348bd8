#pragma once
// Closed form of single scattering from an isotropic point light seen by a
// camera at the origin inside an unbounded homogeneous medium (eta = 1,
// isotropic phase): the reference of the transient_path and transient_beams
// media tests.
//
// Along the camera ray x(s) = s d, light arrives scattered at s after
// travelling l(s) = |x(s) - light|, so at OPL tau(s) = s + l(s). Its radiance,
// per unit s, is sigma_s f_p I / l^2 exp(-sigma_t (s + l)); per unit tau it is
// that divided by d tau / ds = 1 + d.(x - light) / l >= 0. The integral over a
// tau bin is the integral over the s interval that maps to it (tau is
// monotonic in s), computed by Simpson's rule.
#include <cmath>

#include <femto/math/constants.h>
#include <femto/math/vector.h>

namespace femto::test {

struct SingleScattering {
  Vec3f d;                              // unit camera direction
  Point3f light{0.8f, 0.0f, 1.0f};
  double intensity = 2.0;
  double sigmaS = 0.6, sigmaT = 0.8;

  double l(double s) const { return distance(Point3f(d * float(s)), light); }
  double tau(double s) const { return s + l(s); }
  double perUnitS(double s) const {
    double ls = l(s);
    return sigmaS * Inv4Pi * intensity / (ls * ls) * std::exp(-sigmaT * (s + ls));
  }
  /// s with tau(s) = t (bisection; tau increases with s).
  double sOfTau(double t) const {
    double lo = 0.0, hi = 1.0;
    while (tau(hi) < t) hi *= 2.0;
    for (int i = 0; i < 100; ++i) {
      double mid = 0.5 * (lo + hi);
      (tau(mid) < t ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
  double binIntegral(double t0, double t1) const {
    double a = t0 <= tau(0.0) ? 0.0 : sOfTau(t0), b = sOfTau(t1);
    const int n = 200 + 2 * int(std::ceil(100.0 * (b - a)));  // Simpson needs an even count; h <= 0.01
    double h = (b - a) / n, sum = perUnitS(a) + perUnitS(b);
    for (int i = 1; i < n; ++i) sum += perUnitS(a + i * h) * (i % 2 ? 4.0 : 2.0);
    return sum * h / 3.0;
  }
};

}  // namespace femto::test
