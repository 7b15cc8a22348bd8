// sphere: an analytic sphere, intersected exactly (an Embree user geometry in
// the core). `to_world` may rotate, translate and scale uniformly; its scale
// is folded into the radius. uv are spherical coordinates in the sphere's own
// frame: u = phi / 2pi, v = theta / pi.
//
// | name         | type      | default  | meaning                                     | unit        |
// |--------------|-----------|----------|---------------------------------------------|-------------|
// | center       | point     | (0,0,0)  | centre in object space                      | scene units |
// | radius       | float     | 1        | radius in object space                      | scene units |
// | to_world     | transform | identity | object-to-world similarity transform        | -           |
// | flip_normals | boolean   | false    | normals point inward (e.g. a closed room)   | -           |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/shape.h>

namespace femto {

class Sphere final : public Shape {
 public:
  explicit Sphere(const Properties& props) : Shape(props) {
    Point3f center = props.getPoint("center", Point3f(0.0f));
    float radius = props.getFloat("radius", 1.0f, Range::positive());
    Transform toWorld = props.getTransform("to_world", Transform());
    flipNormals_ = props.getBool("flip_normals", false);

    // A sphere stays a sphere only under a similarity.
    float scale = toWorld.similarityScale();
    if (!(scale > 0.0f)) props.raise("to_world", "a sphere's transform may only rotate, translate and scale uniformly");
    frame_ = Frame(toWorld.vector({1, 0, 0}) / scale, toWorld.vector({0, 1, 0}) / scale, toWorld.vector({0, 0, 1}) / scale);
    center_ = toWorld.point(center);
    radius_ = radius * scale;
  }

  BoundingBox3f bbox() const override { return {center_ - Vec3f(radius_), center_ + Vec3f(radius_)}; }
  float surfaceArea() const override { return 4.0f * Pi * radius_ * radius_; }

  PositionSample samplePosition(const Point2f& u) const override {
    Vec3f d = warp::squareToUniformSphere(u);
    PositionSample ps;
    ps.p = center_ + d * radius_;
    ps.n = flipNormals_ ? -d : d;
    ps.uv = sphericalUv(d);
    ps.pdf = 1.0f / surfaceArea();
    return ps;
  }

  /// Ray-sphere intersection in double precision, in the form of Haines et
  /// al., "Precision Improvements for Ray/Sphere Intersection" (Ray Tracing
  /// Gems, ch. 7, eqs. 7.10-7.15): the discriminant is computed from the
  /// distance of the sphere's centre to the ray's line (no cancellation for
  /// small spheres far away) and the roots from the stable quadratic formula
  /// (no cancellation for the near root).
  bool intersect(const Ray& ray, float& t, Point2f& uv) const override {
    Vec3d f = Vec3d(ray.o) - Vec3d(center_);
    Vec3d d(ray.d);
    double a = dot(d, d);
    double b = -dot(f, d);
    Vec3d l = f + d * (b / a);  // from the centre to the closest point of the line
    double r = radius_;
    double discriminant = a * (r * r - dot(l, l));
    if (discriminant < 0.0) return false;
    double c = dot(f, f) - r * r;
    double q = b + std::copysign(std::sqrt(discriminant), b);
    double t0 = c / q, t1 = q / a;
    if (q == 0.0) t0 = t1 = 0.0;  // line tangent to the sphere exactly at the ray origin
    if (t0 > t1) std::swap(t0, t1);
    double tHit = t0 > ray.tmin ? t0 : t1;
    if (!(tHit > ray.tmin && tHit < ray.tmax)) return false;
    t = float(tHit);
    uv = Point2f(0.0f, 0.0f);  // recomputed from the hit point
    return true;
  }

  void computeInteraction(const Ray& ray, float t, uint32_t, const Point2f&, SurfaceInteraction& si) const override {
    // Project the hit back onto the surface: removes the error of o + t d.
    Vec3f d = normalize(ray(t) - center_);
    si.p = center_ + d * radius_;
    si.n = flipNormals_ ? -d : d;
    si.sh = Frame(si.n);
    si.uv = sphericalUv(d);
  }

  std::string toString() const override {
    return str("Sphere[center=", center_, ", radius=", radius_, ", flip_normals=", flipNormals_ ? "true" : "false",
               "]");
  }

 private:
  /// (phi / 2pi, theta / pi) of unit direction `d` in the sphere's frame.
  Point2f sphericalUv(const Vec3f& d) const {
    Vec3f local = frame_.toLocal(d);
    float phi = std::atan2(local.y, local.x);
    if (phi < 0.0f) phi += 2.0f * Pi;
    float theta = std::acos(std::clamp(local.z, -1.0f, 1.0f));
    return {phi * Inv2Pi, theta * InvPi};
  }

  Point3f center_;
  float radius_ = 1.0f;
  Frame frame_;
  bool flipNormals_ = false;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::Sphere, Shape, "sphere", "Analytic sphere")
