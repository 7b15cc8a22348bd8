#include <femto/math/transform.h>

#include <cmath>

#include <femto/base/error.h>
#include <femto/math/constants.h>

namespace femto {

Matrix4f Matrix4f::identity() {
  Matrix4f r;
  for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0f;
  return r;
}

Matrix4f Matrix4f::fromRows(const std::array<float, 16>& v) {
  Matrix4f r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = v[i * 4 + j];
  return r;
}

Matrix4f Matrix4f::operator*(const Matrix4f& o) const {
  Matrix4f r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0.0;
      for (int k = 0; k < 4; ++k) s += double(m[i][k]) * double(o.m[k][j]);
      r.m[i][j] = float(s);
    }
  return r;
}

Matrix4f Matrix4f::transposed() const {
  Matrix4f r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  return r;
}

bool Matrix4f::inverse(Matrix4f& out) const {
  double a[4][8];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      a[i][j] = m[i][j];
      a[i][j + 4] = (i == j) ? 1.0 : 0.0;
    }
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (std::abs(a[pivot][col]) < 1e-12) return false;
    if (pivot != col)
      for (int j = 0; j < 8; ++j) std::swap(a[pivot][j], a[col][j]);
    double inv = 1.0 / a[col][col];
    for (int j = 0; j < 8; ++j) a[col][j] *= inv;
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      double f = a[r][col];
      if (f == 0.0) continue;
      for (int j = 0; j < 8; ++j) a[r][j] -= f * a[col][j];
    }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out.m[i][j] = float(a[i][j + 4]);
  return true;
}

Transform::Transform(const Matrix4f& m) : m_(m) {
  if (!m.inverse(inv_)) throw Error("transform matrix is singular (not invertible)");
}

Point3f Transform::point(const Point3f& p) const {
  const auto& a = m_.m;
  float x = a[0][0] * p.x + a[0][1] * p.y + a[0][2] * p.z + a[0][3];
  float y = a[1][0] * p.x + a[1][1] * p.y + a[1][2] * p.z + a[1][3];
  float z = a[2][0] * p.x + a[2][1] * p.y + a[2][2] * p.z + a[2][3];
  float w = a[3][0] * p.x + a[3][1] * p.y + a[3][2] * p.z + a[3][3];
  return w == 1.0f ? Point3f(x, y, z) : Point3f(x, y, z) / w;
}

Vec3f Transform::vector(const Vec3f& v) const {
  const auto& a = m_.m;
  return {a[0][0] * v.x + a[0][1] * v.y + a[0][2] * v.z,
          a[1][0] * v.x + a[1][1] * v.y + a[1][2] * v.z,
          a[2][0] * v.x + a[2][1] * v.y + a[2][2] * v.z};
}

Normal3f Transform::normal(const Normal3f& n) const {
  const auto& b = inv_.m;  // multiply by the transpose of the inverse
  return {b[0][0] * n.x + b[1][0] * n.y + b[2][0] * n.z,
          b[0][1] * n.x + b[1][1] * n.y + b[2][1] * n.z,
          b[0][2] * n.x + b[1][2] * n.y + b[2][2] * n.z};
}

Ray Transform::ray(const Ray& r) const { return Ray(point(r.o), vector(r.d), r.tmin, r.tmax); }

BoundingBox3f Transform::bbox(const BoundingBox3f& b) const {
  BoundingBox3f out;
  if (!b.valid()) return out;
  for (int i = 0; i < 8; ++i)
    out.expand(point(Point3f(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z)));
  return out;
}

bool Transform::flipsHandedness() const {
  const auto& a = m_.m;
  double det = a[0][0] * (double(a[1][1]) * a[2][2] - double(a[1][2]) * a[2][1]) -
               a[0][1] * (double(a[1][0]) * a[2][2] - double(a[1][2]) * a[2][0]) +
               a[0][2] * (double(a[1][0]) * a[2][1] - double(a[1][1]) * a[2][0]);
  return det < 0.0;
}

float Transform::similarityScale() const {
  Vec3f axes[3] = {vector({1, 0, 0}), vector({0, 1, 0}), vector({0, 0, 1})};
  float scale = length(axes[0]);
  if (!(scale > 0.0f)) return 0.0f;
  for (auto& axis : axes) {
    if (std::abs(length(axis) - scale) > 1e-4f * scale) return 0.0f;
    axis = axis / scale;
  }
  if (std::abs(dot(axes[0], axes[1])) > 1e-4f || std::abs(dot(axes[0], axes[2])) > 1e-4f ||
      std::abs(dot(axes[1], axes[2])) > 1e-4f)
    return 0.0f;
  return scale;
}

Transform Transform::translate(const Vec3f& t) {
  Matrix4f m = Matrix4f::identity(), inv = Matrix4f::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][3] = t[i];
    inv.m[i][3] = -t[i];
  }
  return Transform(m, inv);
}

Transform Transform::scale(const Vec3f& s) {
  if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) throw Error("scale by zero is not invertible");
  Matrix4f m = Matrix4f::identity(), inv = Matrix4f::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][i] = s[i];
    inv.m[i][i] = 1.0f / s[i];
  }
  return Transform(m, inv);
}

Transform Transform::rotate(const Vec3f& axis, float angleDeg) {
  if (squaredLength(axis) == 0.0f) throw Error("rotation axis has zero length");
  Vec3f a = normalize(axis);
  double th = double(angleDeg) * 3.14159265358979323846 / 180.0;
  double s = std::sin(th), c = std::cos(th), t = 1.0 - c;
  Matrix4f m = Matrix4f::identity();
  m.m[0][0] = float(a.x * a.x * t + c);
  m.m[0][1] = float(a.x * a.y * t - a.z * s);
  m.m[0][2] = float(a.x * a.z * t + a.y * s);
  m.m[1][0] = float(a.y * a.x * t + a.z * s);
  m.m[1][1] = float(a.y * a.y * t + c);
  m.m[1][2] = float(a.y * a.z * t - a.x * s);
  m.m[2][0] = float(a.z * a.x * t - a.y * s);
  m.m[2][1] = float(a.z * a.y * t + a.x * s);
  m.m[2][2] = float(a.z * a.z * t + c);
  return Transform(m, m.transposed());  // rotations are orthogonal
}

Transform Transform::lookAt(const Point3f& origin, const Point3f& target, const Vec3f& up) {
  Vec3f dir = target - origin;
  if (squaredLength(dir) == 0.0f) throw Error("lookat: origin and target coincide");
  dir = normalize(dir);
  Vec3f left = cross(up, dir);
  if (squaredLength(left) < 1e-12f) throw Error("lookat: 'up' is parallel to the viewing direction");
  left = normalize(left);
  Vec3f newUp = cross(dir, left);
  Matrix4f m = Matrix4f::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][0] = left[i];
    m.m[i][1] = newUp[i];
    m.m[i][2] = dir[i];
    m.m[i][3] = origin[i];
  }
  return Transform(m);
}

Transform Transform::perspective(float fovDeg, float n, float f) {
  float recip = 1.0f / (f - n);
  float cot = 1.0f / std::tan(degToRad(fovDeg) * 0.5f);
  Matrix4f p = Matrix4f::fromRows({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, f * recip, -n * f * recip, 0, 0, 1, 0});
  return Transform::scale(Vec3f(cot, cot, 1.0f)) * Transform(p);
}

std::ostream& operator<<(std::ostream& os, const Matrix4f& m) {
  os << '[';
  for (int i = 0; i < 4; ++i) {
    os << (i ? ", [" : "[");
    for (int j = 0; j < 4; ++j) os << (j ? ", " : "") << m.m[i][j];
    os << ']';
  }
  return os << ']';
}

}  // namespace femto
