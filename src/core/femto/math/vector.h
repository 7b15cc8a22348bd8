#pragma once
// Small fixed-size vectors. Points, vectors and normals share one type (Vec3f);
// what differs is how a Transform maps them (Transform::point/vector/normal).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>

namespace femto {

template <typename T>
struct Vec2 {
  T x{}, y{};
  constexpr Vec2() = default;
  constexpr Vec2(T x_, T y_) : x(x_), y(y_) {}
  constexpr explicit Vec2(T v) : x(v), y(v) {}
  constexpr T operator[](int i) const { return i == 0 ? x : y; }
  constexpr T& operator[](int i) { return i == 0 ? x : y; }
  constexpr Vec2 operator+(const Vec2& o) const { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(const Vec2& o) const { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator*(T s) const { return {x * s, y * s}; }
  constexpr Vec2 operator*(const Vec2& o) const { return {x * o.x, y * o.y}; }
  constexpr Vec2 operator/(T s) const { return {x / s, y / s}; }
  constexpr bool operator==(const Vec2& o) const = default;
};

template <typename T>
struct Vec3 {
  T x{}, y{}, z{};
  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  constexpr explicit Vec3(T v) : x(v), y(v), z(v) {}
  template <typename U>
  constexpr explicit Vec3(const Vec3<U>& o) : x(T(o.x)), y(T(o.y)), z(T(o.z)) {}

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
  constexpr Vec3 operator/(const Vec3& o) const { return {x / o.x, y / o.y, z / o.z}; }
  constexpr Vec3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(T s) const { T inv = T(1) / s; return {x * inv, y * inv, z * inv}; }
  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
  constexpr bool operator==(const Vec3& o) const = default;
};

template <typename T> constexpr Vec3<T> operator*(T s, const Vec3<T>& v) { return v * s; }
template <typename T> constexpr Vec2<T> operator*(T s, const Vec2<T>& v) { return v * s; }
template <typename T> constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename T> constexpr T absDot(const Vec3<T>& a, const Vec3<T>& b) { return std::abs(dot(a, b)); }
template <typename T> constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T> inline T squaredLength(const Vec3<T>& v) { return dot(v, v); }
template <typename T> inline T length(const Vec3<T>& v) { return std::sqrt(dot(v, v)); }
template <typename T> inline Vec3<T> normalize(const Vec3<T>& v) { return v / length(v); }
template <typename T> inline T distance(const Vec3<T>& a, const Vec3<T>& b) { return length(a - b); }
template <typename T> inline Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
template <typename T> inline Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
template <typename T> inline Vec3<T> abs(const Vec3<T>& v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
template <typename T> inline T maxComponent(const Vec3<T>& v) { return std::max(v.x, std::max(v.y, v.z)); }
template <typename T> inline bool isFinite(const Vec3<T>& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
/// Mirror `wi` about `n` (both pointing away from the surface).
template <typename T> inline Vec3<T> reflect(const Vec3<T>& wi, const Vec3<T>& n) { return n * (T(2) * dot(wi, n)) - wi; }
/// Flip `n` into the hemisphere of `v`.
template <typename T> inline Vec3<T> faceForward(const Vec3<T>& n, const Vec3<T>& v) { return dot(n, v) < T(0) ? -n : n; }

template <typename T> std::ostream& operator<<(std::ostream& os, const Vec3<T>& v) { return os << '[' << v.x << ", " << v.y << ", " << v.z << ']'; }
template <typename T> std::ostream& operator<<(std::ostream& os, const Vec2<T>& v) { return os << '[' << v.x << ", " << v.y << ']'; }

using Vec2f = Vec2<float>;
using Vec2i = Vec2<int>;
using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;
using Point2f = Vec2f;
using Point2i = Vec2i;
using Point3f = Vec3f;
using Normal3f = Vec3f;

}  // namespace femto
