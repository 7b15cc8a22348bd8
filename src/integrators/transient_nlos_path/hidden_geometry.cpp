#include "hidden_geometry.h"

#include <algorithm>
#include <cmath>

#include <femto/render/shape.h>
#include <femto/render/shape_group.h>

namespace femto {

HiddenGeometry::HiddenGeometry(const Scene& scene, const Shape* wall, bool includeWall) {
  for (const auto& shape : scene.shapes()) {
    if (shape.get() == wall && !includeWall) continue;
    if (dynamic_cast<const ShapeGroup*>(shape.get()) || dynamic_cast<const ShapeInstance*>(shape.get())) continue;
    float area = shape->surfaceArea();
    if (!(area > 0.0f)) continue;
    totalArea_ += area;
    shapes_.push_back(shape.get());
    cdf_.push_back(totalArea_);
  }
}

bool HiddenGeometry::sampleable(const Shape* shape) const {
  return std::find(shapes_.begin(), shapes_.end(), shape) != shapes_.end();
}

bool HiddenGeometry::sampleDirection(const SurfaceInteraction& ref, const Point2f& u, Vec3f& d) const {
  if (empty()) return false;
  // Pick a shape by area and reuse the part of u.x inside its interval.
  float target = u.x * totalArea_;
  size_t i = std::min(size_t(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()), cdf_.size() - 1);
  float start = i == 0 ? 0.0f : cdf_[i - 1];
  float reused = std::clamp((target - start) / (cdf_[i] - start), 0.0f, 0.99999994f);
  PositionSample ps = shapes_[i]->samplePosition(Point2f(reused, u.y));
  Vec3f v = ps.p - ref.offsetOrigin(ps.p - ref.p);
  float len = length(v);
  if (!(len > 0.0f)) return false;
  d = v / len;
  return true;
}

float HiddenGeometry::pdf(const Scene& scene, const SurfaceInteraction& ref, const Vec3f& d) const {
  if (empty()) return 0.0f;
  // Walk the whole line: every sampleable surface point on it could have been the one chosen.
  double sum = 0.0;
  Ray ray = ref.spawnRay(d);
  const Point3f origin = ray.o;
  for (int crossing = 0; crossing < 64; ++crossing) {
    SurfaceInteraction hit;
    if (!scene.rayIntersect(ray, hit)) break;
    if (sampleable(hit.shape)) {
      float cosine = std::abs(dot(hit.n, d));
      float dist = distance(origin, hit.p);
      if (cosine > 0.0f) sum += double(dist) * dist / (double(cosine) * totalArea_);
    }
    ray = hit.spawnRay(d);
  }
  return float(sum);
}

}  // namespace femto
