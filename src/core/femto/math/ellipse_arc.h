#pragma once
// Arc length on the ellipse e(phi) = U cos(phi) + V sin(phi) (U, V any two
// non-parallel 3D vectors): its perimeter and angles drawn uniformly by arc
// length. An affinely mapped tube has exactly this profile: the area element
// of M (cos phi, sin phi, z) is |(M e_phi) x (M e_z)| dphi dz, the speed of
// such an ellipse, so the `cylinder` shape takes its area and its uniform
// position samples from here under any to_world.
//
// The perimeter is an elliptic integral without a closed form; it is
// tabulated on Intervals equal angle intervals, each integrated by 4-point
// Gauss-Legendre quadrature (the speed is smooth and periodic). Against the
// exact AGM perimeter the relative error is ~1e-16 for axis ratios up to 4,
// below 1e-9 up to 50 and 1e-7 up to 1000 (tests/unit/plugins/shapes/test_cylinder_affine.cpp).
// Inversion finishes with safeguarded Newton steps on the same quadrature, so
// samples follow the speed, not a piecewise-constant stand-in for it.
#include <vector>

#include <femto/math/vector.h>

namespace femto {

class EllipseArc {
 public:
  static constexpr int Intervals = 256;

  EllipseArc() = default;
  /// U and V must not be parallel (the ellipse would be a segment).
  EllipseArc(const Vec3d& u, const Vec3d& v);

  /// |de/dphi| = |-U sin(phi) + V cos(phi)|.
  double speed(double phi) const;
  /// The whole arc length, phi from 0 to 2 pi.
  double perimeter() const { return perimeter_; }
  /// The angle in [0, 2 pi) at which the arc length from phi = 0 is
  /// `fraction` (in [0, 1]) of the perimeter.
  double angleAtFraction(double fraction) const;
  /// True when the ellipse is a circle (constant speed): angleAtFraction is
  /// then exactly 2 pi fraction.
  bool isCircle() const { return circle_; }

 private:
  /// Arc length from `a` to `b` (b - a at most one interval), by Gauss-Legendre.
  double arcLength(double a, double b) const;

  Vec3d u_, v_;
  double perimeter_ = 0.0;
  bool circle_ = true;
  std::vector<double> cumulative_;  // arc length from 0 to the start of each interval; Intervals + 1 entries
};

}  // namespace femto
