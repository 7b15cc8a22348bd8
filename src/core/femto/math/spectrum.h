#pragma once
// Linear RGB radiometric quantities (femto renders in RGB, like Mitsuba's rgb variants).
#include <algorithm>
#include <cmath>
#include <ostream>

namespace femto {

struct Color3f {
  float r = 0, g = 0, b = 0;
  constexpr Color3f() = default;
  constexpr explicit Color3f(float v) : r(v), g(v), b(v) {}
  constexpr Color3f(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}

  constexpr float operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
  constexpr float& operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }
  constexpr Color3f operator+(const Color3f& o) const { return {r + o.r, g + o.g, b + o.b}; }
  constexpr Color3f operator-(const Color3f& o) const { return {r - o.r, g - o.g, b - o.b}; }
  constexpr Color3f operator*(const Color3f& o) const { return {r * o.r, g * o.g, b * o.b}; }
  constexpr Color3f operator/(const Color3f& o) const { return {r / o.r, g / o.g, b / o.b}; }
  constexpr Color3f operator*(float s) const { return {r * s, g * s, b * s}; }
  constexpr Color3f operator/(float s) const { return {r / s, g / s, b / s}; }
  constexpr Color3f& operator+=(const Color3f& o) { r += o.r; g += o.g; b += o.b; return *this; }
  constexpr Color3f& operator*=(const Color3f& o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
  constexpr Color3f& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
  constexpr bool operator==(const Color3f& o) const = default;

  constexpr bool isBlack() const { return r == 0 && g == 0 && b == 0; }
  constexpr float maxValue() const { return std::max(r, std::max(g, b)); }
  constexpr float average() const { return (r + g + b) / 3.0f; }
  /// Rec. 709 luminance.
  constexpr float luminance() const { return 0.212671f * r + 0.715160f * g + 0.072169f * b; }
  bool isFinite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
  /// Finite and non-negative: what may be added to a film.
  bool isValid() const { return isFinite() && r >= 0 && g >= 0 && b >= 0; }
};

constexpr Color3f operator*(float s, const Color3f& c) { return c * s; }
inline std::ostream& operator<<(std::ostream& os, const Color3f& c) { return os << '[' << c.r << ", " << c.g << ", " << c.b << ']'; }

using Spectrum = Color3f;

}  // namespace femto
