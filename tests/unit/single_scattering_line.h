#pragma once
// Closed form of single scattering from an isotropic point light along one
// camera ray, time-resolved: the reference of transient_beams' default-
// settings and randomised media tests. More general than
// single_scattering_model.h: a homogeneous medium filling space or a sphere
// (vacuum outside, index-matched boundary: no refraction), refractive index
// eta, isotropic phase, camera and light inside or outside, observer time on
// or off.
//
// Along the ray x(s) = o + s d the light scattered at s has travelled
// l(s) = |x(s) - light|, of which l_in(s) inside the medium; the ray's part
// inside the medium is [s0, s1]. Per unit s the radiance is
//   sigma_s / (4 pi) I / l^2 exp(-sigma_t ((s - s0) + l_in))
// (transmittance along the camera ray from where it enters and along the
// light's path inside the medium), at OPL
//   tau(s) = [observer time] (s0 + eta (s - s0)) + (l - l_in) + eta l_in
// (vacuum parts count 1 per unit length). tau is not monotonic in s without
// observer time, so the reference marches s in fine steps and spreads each
// step's mass uniformly over the OPLs its ends map to (piecewise linear in
// s): exact as the step shrinks, 2e5 steps here.
#include <algorithm>
#include <cmath>
#include <vector>

#include <femto/math/constants.h>
#include <femto/math/vector.h>
#include <femto/time/time_grid.h>

namespace femto::test {

struct SingleScatteringLine {
  Point3f light{0.0f};
  double intensity = 1.0;
  double sigmaS = 0.5, sigmaT = 1.0, eta = 1.0;
  bool bounded = false;  // false: the medium fills space
  Point3f center{0.0f};  // of the spherical medium, when bounded
  double radius = 1.0;
  bool observerTime = true;

  /// [t0, t1] of the ray o + t d inside the medium (t >= 0); false if it misses.
  bool inside(const Point3f& o, const Vec3f& d, double tEnd, double& t0, double& t1) const {
    if (!bounded) {
      t0 = 0.0, t1 = tEnd;
      return tEnd > 0.0;
    }
    const double ox = o.x - center.x, oy = o.y - center.y, oz = o.z - center.z;
    const double b = ox * d.x + oy * d.y + oz * d.z, c = ox * ox + oy * oy + oz * oz - radius * radius;
    const double disc = b * b - c;
    if (!(disc > 0.0)) return false;
    t0 = std::max(0.0, -b - std::sqrt(disc)), t1 = std::min(tEnd, -b + std::sqrt(disc));
    return t1 > t0;
  }
  /// Length of the straight path light -> p inside the medium.
  double lengthInside(const Point3f& p) const {
    const Vec3f toP = p - light;
    const double l = length(toP);
    if (!bounded || !(l > 0.0)) return l;
    double t0 = 0.0, t1 = 0.0;
    return inside(light, toP / float(l), l, t0, t1) ? t1 - t0 : 0.0;
  }

  /// Time-resolved radiance along o + s d (unit d) deposited into `grid`'s
  /// bins (entries: bins; the steady total in `total`). `reach`: how far an
  /// unbounded ray is followed (its tail is negligible, exp(-sigma_t reach)).
  std::vector<double> bins(const Point3f& o, const Vec3f& d, const TimeGrid& grid, double& total, double reach = 40.0,
                           int steps = 200000) const {
    std::vector<double> out(size_t(grid.bins), 0.0);
    total = 0.0;
    double s0 = 0.0, s1 = 0.0;
    if (!inside(o, d, bounded ? 1e30 : reach / sigmaT, s0, s1)) return out;
    auto tau = [&](double s) {
      const Point3f x = o + d * float(s);
      const double l = distance(x, light), lin = lengthInside(x);
      return (observerTime ? s0 + eta * (s - s0) : 0.0) + (l - lin) + eta * lin;
    };
    auto perUnitS = [&](double s) {
      const Point3f x = o + d * float(s);
      const double l = distance(x, light);
      return sigmaS * Inv4Pi * intensity / (l * l) * std::exp(-sigmaT * ((s - s0) + lengthInside(x)));
    };
    const double h = (s1 - s0) / steps;
    double tauA = tau(s0);
    for (int i = 0; i < steps; ++i) {
      const double a = s0 + i * h, tauB = tau(a + h);
      const double mass = perUnitS(a + 0.5 * h) * h;
      total += mass;
      const double lo = std::min(tauA, tauB), hi = std::max(tauA, tauB);
      const int first = int(std::floor((lo - grid.start) / grid.binWidth));
      const int last = int(std::floor((hi - grid.start) / grid.binWidth));
      for (int b = std::max(first, 0); b <= std::min(last, grid.bins - 1); ++b) {
        const double bl = grid.start + b * grid.binWidth, bh = bl + grid.binWidth;
        const double share = hi > lo ? (std::min(hi, bh) - std::max(lo, bl)) / (hi - lo) : 1.0;
        out[size_t(b)] += mass * share;
      }
      tauA = tauB;
    }
    return out;
  }
};

}  // namespace femto::test
