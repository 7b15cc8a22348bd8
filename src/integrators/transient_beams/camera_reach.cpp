#include <transient_beams/camera_reach.h>

#include <algorithm>

#include <femto/render/film.h>
#include <femto/render/projective_camera.h>
#include <femto/render/scene.h>

namespace femto::beams {

CameraReach cameraReach(const Scene& scene, bool observerTime) {
  CameraReach reach;
  const auto* camera = dynamic_cast<const ProjectiveCamera*>(&scene.sensor());
  if (!observerTime || !camera) return reach;
  // Ray origins at the film's corners and centre through the aperture's
  // corners and centre: their convex hull holds every origin (a pinhole's
  // single point, points on the near plane, a thin lens's disc), and so
  // does the ball around their mean reaching the farthest.
  const Point2i size = scene.sensor().film().size();
  const float fx[3] = {0.0f, 0.5f * float(size.x), float(size.x)}, fy[3] = {0.0f, 0.5f * float(size.y), float(size.y)};
  const float u[3] = {0.0f, 0.5f, 1.0f};
  std::vector<Point3f> origins;
  for (float x : fx)
    for (float y : fy)
      for (float a : u)
        for (float b : u) {
          Ray ray;
          scene.sensor().sampleRay(Point2f(x, y), Point2f(a, b), ray);
          origins.push_back(ray.o);
        }
  Vec3f sum(0.0f);
  for (const Point3f& o : origins) sum += Vec3f(o.x, o.y, o.z);
  reach.center = Point3f(0.0f) + sum / float(origins.size());
  for (const Point3f& o : origins) reach.radius = std::max(reach.radius, femto::distance(o, reach.center));
  reach.radius *= 1.0001f;  // float rounding of the corners
  reach.valid = std::isfinite(reach.radius);
  return reach;
}

float reachableLength(const CameraReach& reach, const Point3f& origin, const Vec3f& dir, float length, double opl,
                      float eta, double limit) {
  auto late = [&](float s) { return opl + double(eta) * s + reach.distance(origin + dir * s) >= limit; };
  if (!reach.valid || !late(length)) return length;
  if (late(0.0f)) return 0.0f;
  float lo = 0.0f, hi = length;  // late(hi), !late(lo)
  for (int i = 0; i < 40 && hi - lo > 1e-6f * std::max(1.0f, hi); ++i) {
    const float mid = 0.5f * (lo + hi);
    (late(mid) ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace femto::beams
