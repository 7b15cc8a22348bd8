#pragma once
// Affine/projective 4x4 transforms with their cached inverse.
#include <array>
#include <ostream>

#include <femto/math/bbox.h>
#include <femto/math/ray.h>
#include <femto/math/vector.h>

namespace femto {

/// Row-major 4x4 matrix: m[row][col]; points are column vectors (M * p).
struct Matrix4f {
  std::array<std::array<float, 4>, 4> m{};

  static Matrix4f identity();
  static Matrix4f fromRows(const std::array<float, 16>& values);
  Matrix4f operator*(const Matrix4f& o) const;
  Matrix4f transposed() const;
  /// Inverse by Gauss-Jordan elimination with partial pivoting (in double).
  /// Returns false, leaving `out` untouched, when the matrix is singular.
  bool inverse(Matrix4f& out) const;
  bool operator==(const Matrix4f& o) const = default;
};

class Transform {
 public:
  Transform() : m_(Matrix4f::identity()), inv_(Matrix4f::identity()) {}
  /// Throws femto::Error when `m` is singular.
  explicit Transform(const Matrix4f& m);
  Transform(const Matrix4f& m, const Matrix4f& inv) : m_(m), inv_(inv) {}

  const Matrix4f& matrix() const { return m_; }
  const Matrix4f& inverseMatrix() const { return inv_; }
  Transform inverse() const { return Transform(inv_, m_); }
  /// Composition: (a * b).point(p) == a.point(b.point(p)).
  Transform operator*(const Transform& o) const { return Transform(m_ * o.m_, o.inv_ * inv_); }

  Point3f point(const Point3f& p) const;      // includes translation and projective divide
  Vec3f vector(const Vec3f& v) const;         // ignores translation
  Normal3f normal(const Normal3f& n) const;   // inverse transpose (not normalised)
  Ray ray(const Ray& r) const;                // transforms origin and direction, keeps t range
  BoundingBox3f bbox(const BoundingBox3f& b) const;
  bool isIdentity() const { return m_ == Matrix4f::identity(); }
  /// True when the transform flips handedness (negative determinant of the 3x3 part).
  bool flipsHandedness() const;
  /// The scale factor s when the linear part is s times an orthogonal matrix
  /// (rotation, reflection, uniform scale: shapes keep their form), else 0.
  /// Tolerance: relative 1e-4 on lengths and cosines.
  float similarityScale() const;

  static Transform translate(const Vec3f& t);
  static Transform scale(const Vec3f& s);
  /// Rotation by `angleDeg` degrees about `axis` (right-handed).
  static Transform rotate(const Vec3f& axis, float angleDeg);
  /// Camera-to-world transform: camera at `origin`, looking at `target`, with
  /// `up` as the approximate up direction (Mitsuba convention: +z looks forward,
  /// +x left, +y up in camera space).
  static Transform lookAt(const Point3f& origin, const Point3f& target, const Vec3f& up);
  /// Perspective projection with horizontal field of view `fovDeg` mapping the
  /// camera frustum to z in [0, 1] between `nearClip` and `farClip`.
  static Transform perspective(float fovDeg, float nearClip, float farClip);

 private:
  Matrix4f m_, inv_;
};

std::ostream& operator<<(std::ostream& os, const Matrix4f& m);

}  // namespace femto
