#pragma once
// Orthonormal frame used to express directions in a local shading space,
// where the normal is +z (so cosTheta(w) == w.z).
#include <femto/math/vector.h>

namespace femto {

struct Frame {
  Vec3f s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};

  Frame() = default;
  Frame(const Vec3f& s_, const Vec3f& t_, const Vec3f& n_) : s(s_), t(t_), n(n_) {}
  /// Branchless orthonormal basis around a unit normal
  /// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
  explicit Frame(const Vec3f& normal) : n(normal) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    s = Vec3f(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3f(b, sign + n.y * n.y * a, -n.y);
  }
  Vec3f toLocal(const Vec3f& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vec3f toWorld(const Vec3f& v) const { return s * v.x + t * v.y + n * v.z; }

  static float cosTheta(const Vec3f& w) { return w.z; }
  static float cos2Theta(const Vec3f& w) { return w.z * w.z; }
  static float sin2Theta(const Vec3f& w) { return std::max(0.0f, 1.0f - w.z * w.z); }
  static float sinTheta(const Vec3f& w) { return std::sqrt(sin2Theta(w)); }
  static float tanTheta(const Vec3f& w) { return sinTheta(w) / w.z; }
};

}  // namespace femto
