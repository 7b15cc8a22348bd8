// disk: the unit disk x^2 + y^2 <= 1 in the plane z = 0, facing +z (as
// Mitsuba 3), intersected exactly (an Embree user geometry in the core).
// `to_world` may be any affine transform: the disk becomes an ellipse, still
// flat, so hits and uniform area sampling stay exact. uv = (r, phi / 2pi) as
// in Mitsuba 3.
//
// | name         | type      | default  | meaning                                   | unit |
// |--------------|-----------|----------|-------------------------------------------|------|
// | to_world     | transform | identity | object-to-world placement (affine)        | -    |
// | flip_normals | boolean   | false    | the disk faces -z instead                 | -    |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/shape.h>

namespace femto {

class Disk final : public Shape {
 public:
  explicit Disk(const Properties& props) : Shape(props) {
    toWorld_ = props.getTransform("to_world", Transform());
    toLocal_ = toWorld_.inverse();
    flipNormals_ = props.getBool("flip_normals", false);
    Vec3f dpdx = toWorld_.vector({1, 0, 0}), dpdy = toWorld_.vector({0, 1, 0});
    // An affine map scales every area of the plane by |dp/dx x dp/dy|.
    area_ = Pi * length(cross(dpdx, dpdy));
    if (!(area_ > 0.0f)) props.raise("to_world", "the transform flattens the disk to zero area");
    Normal3f n = normalize(toWorld_.normal({0, 0, 1}));
    normal_ = flipNormals_ ? -n : n;
  }

  BoundingBox3f bbox() const override { return toWorld_.bbox({Point3f(-1, -1, 0), Point3f(1, 1, 0)}); }
  float surfaceArea() const override { return area_; }

  PositionSample samplePosition(const Point2f& u) const override {
    // Uniform on the unit disk stays uniform under an affine map (constant Jacobian).
    Point2f q = warp::squareToUniformDiskConcentric(u);
    PositionSample ps;
    ps.p = toWorld_.point(Point3f(q.x, q.y, 0.0f));
    ps.n = normal_;
    ps.uv = polarUv(q);
    ps.pdf = 1.0f / area_;
    return ps;
  }

  /// In object space the plane is z = 0: t = -o.z / d.z. The object-space
  /// direction is not normalised, so t is the world ray's own parameter.
  bool intersect(const Ray& ray, float& t, Point2f& uv) const override {
    Ray local = toLocal_.ray(ray);
    if (local.d.z == 0.0f) return false;  // parallel to the plane
    float tHit = -local.o.z / local.d.z;
    if (!(tHit > ray.tmin && tHit < ray.tmax)) return false;
    float x = local.o.x + tHit * local.d.x, y = local.o.y + tHit * local.d.y;
    if (x * x + y * y > 1.0f) return false;
    t = tHit;
    uv = Point2f(x, y);  // local hit point, for computeInteraction
    return true;
  }

  void computeInteraction(const Ray&, float, uint32_t, const Point2f& xy, SurfaceInteraction& si) const override {
    // The local point with z = 0 exactly: the hit lies on the plane.
    si.p = toWorld_.point(Point3f(xy.x, xy.y, 0.0f));
    si.n = normal_;
    si.sh = Frame(normal_);
    si.uv = polarUv(xy);
  }

  std::string toString() const override {
    return str("Disk[area=", area_, ", normal=", normal_, ", flip_normals=", flipNormals_ ? "true" : "false", "]");
  }

 private:
  static Point2f polarUv(const Point2f& q) {
    float phi = std::atan2(q.y, q.x);
    if (phi < 0.0f) phi += 2.0f * Pi;
    return {std::sqrt(q.x * q.x + q.y * q.y), phi * Inv2Pi};
  }

  Transform toWorld_, toLocal_;
  Normal3f normal_;
  float area_ = 0.0f;
  bool flipNormals_ = false;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::Disk, Shape, "disk", "Analytic disk")
