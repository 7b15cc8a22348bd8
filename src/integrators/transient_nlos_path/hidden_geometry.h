#pragma once
// Hidden-geometry sampling (Royo et al., "Non-line-of-sight transient
// rendering", C&G 2022, sec. 4.2): from a path vertex, pick the next
// direction toward a point chosen uniformly by area on the hidden geometry
// (every shape but the relay wall, unless it is included), instead of from
// the BSDF. Most directions from the relay wall see nothing; these all see
// the hidden scene.
//
// A direction is produced by every sampleable point on its line, not only the
// first one the ray meets (a closed object is crossed twice), so its
// solid-angle density sums p_A d^2 / |cos| over all of them (pdf()).
// Directions and distances are taken from the origin of the ray that leaves
// the vertex (offset off its surface), so the ray meets the chosen point:
// from the vertex itself, points within the offset's parallax of an edge
// (~1e-4) would be missed, a bias of a few tenths of a percent on a small
// hidden square (TransientNlosPath tests).
#include <vector>

#include <femto/render/interaction.h>
#include <femto/render/scene.h>

namespace femto {

class HiddenGeometry {
 public:
  /// The shapes of `scene` that can be sampled, weighted by area; the relay
  /// wall `wall` is left out unless `includeWall`. Shape groups and instances
  /// are never sampled.
  HiddenGeometry(const Scene& scene, const Shape* wall, bool includeWall);

  bool empty() const { return !(totalArea_ > 0.0f); }
  /// A unit direction from `ref` toward a uniformly chosen hidden point.
  bool sampleDirection(const SurfaceInteraction& ref, const Point2f& u, Vec3f& d) const;
  /// The solid-angle density with which sampleDirection picks `d` from `ref`.
  float pdf(const Scene& scene, const SurfaceInteraction& ref, const Vec3f& d) const;

 private:
  bool sampleable(const Shape* shape) const;

  std::vector<const Shape*> shapes_;
  std::vector<float> cdf_;
  float totalArea_ = 0.0f;
};

}  // namespace femto
