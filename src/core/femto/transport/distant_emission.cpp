#include <femto/transport/distant_emission.h>

#include <femto/math/constants.h>
#include <femto/math/frame.h>
#include <femto/math/warp.h>
#include <femto/render/scene.h>

namespace femto {

SceneSphere SceneSphere::of(const Scene& scene) {
  SceneSphere s;
  const BoundingBox3f& box = scene.bbox();
  if (box.valid()) {
    s.center = box.center();
    // A flat or point-like scene still needs a disk of some size to emit from.
    s.radius = std::max(box.boundingRadius(), 1e-3f * std::max(1.0f, length(box.center())));
  }
  return s;
}

float SceneSphere::diskArea() const { return Pi * radius * radius; }

Ray SceneSphere::rayAlong(const Vec3f& d, const Point2f& u) const {
  Point2f disk = warp::squareToUniformDiskConcentric(u);
  Frame frame(d);
  Point3f origin = center + (frame.s * disk.x + frame.t * disk.y - d) * radius;
  return Ray(origin, d);
}

Point3f SceneSphere::pointAtInfinity(const Point3f& ref, const Vec3f& d) const {
  return ref + d * (2.0f * radius + distance(ref, center));
}

}  // namespace femto

namespace femto {

DirectionSample SceneSphere::directionSample(const Point3f& ref, const Vec3f& d) const {
  DirectionSample ds;
  ds.d = d;
  ds.dist = Infinity;
  ds.p = pointAtInfinity(ref, d);
  ds.n = -d;
  return ds;
}

}  // namespace femto
