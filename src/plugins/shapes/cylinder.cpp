// cylinder: the open tube of radius `radius` around the segment p0 -> p1 (no
// caps, as Mitsuba 3), intersected exactly (an Embree user geometry in the
// core). Normals point away from the axis unless flip_normals. uv =
// (phi / 2pi, height fraction from p0), as in Mitsuba 3.
//
// Any affine to_world is rendered as it says: the tube is intersected in
// object space (the unit tube x^2 + y^2 = 1, 0 <= z <= 1), normals are mapped
// by the inverse transpose, and a scale that differs between x and y (or a
// shear) gives an elliptic tube whose area and uniform position samples come
// from the exact arc length of its cross-section (math/ellipse_arc.h).
// Mitsuba 3 keeps a different axis scale (x = y != z) but warns about unequal
// x and y scales or shear and then renders a circular tube of the x scale;
// femto renders the ellipse.
//
// | name         | type      | default  | meaning                                   | unit        |
// |--------------|-----------|----------|-------------------------------------------|-------------|
// | p0           | point     | (0,0,0)  | centre of the first end                   | scene units |
// | p1           | point     | (0,0,1)  | centre of the second end                  | scene units |
// | radius       | float     | 1        | radius                                    | scene units |
// | to_world     | transform | identity | object-to-world affine transform          | -           |
// | flip_normals | boolean   | false    | normals point toward the axis             | -           |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/math/ellipse_arc.h>
#include <femto/render/shape.h>

namespace femto {

class Cylinder final : public Shape {
 public:
  explicit Cylinder(const Properties& props) : Shape(props) {
    Point3f p0 = props.getPoint("p0", Point3f(0.0f, 0.0f, 0.0f));
    Point3f p1 = props.getPoint("p1", Point3f(0.0f, 0.0f, 1.0f));
    float radius = props.getFloat("radius", 1.0f, Range::positive());
    Transform toWorld = props.getTransform("to_world", Transform());
    flipNormals_ = props.getBool("flip_normals", false);
    Vec3f axis = p1 - p0;
    float height = length(axis);
    if (!(height > 0.0f)) props.raise("p1", "must differ from p0");

    // Object space: the unit cylinder x^2 + y^2 = 1, 0 <= z <= 1.
    Frame frame(axis / height);
    Matrix4f basis = Matrix4f::fromRows({frame.s.x, frame.t.x, frame.n.x, 0.0f,  //
                                         frame.s.y, frame.t.y, frame.n.y, 0.0f,  //
                                         frame.s.z, frame.t.z, frame.n.z, 0.0f,  //
                                         0.0f, 0.0f, 0.0f, 1.0f});
    toWorld_ = toWorld * Transform::translate(p0) * Transform(basis) * Transform::scale({radius, radius, height});
    toLocal_ = toWorld_.inverse();
    // Area element of the mapped tube: |(M e_phi) x (M e_z)| dphi dz with
    // M e_phi = -sin(phi) X + cos(phi) Y, i.e. the speed of the ellipse
    // (X x Z) cos(phi) + (Y x Z) sin(phi); z enters linearly.
    Vec3d x(toWorld_.vector({1, 0, 0})), y(toWorld_.vector({0, 1, 0})), z(toWorld_.vector({0, 0, 1}));
    try {
      profile_ = EllipseArc(cross(x, z), cross(y, z));
    } catch (const Error&) {
      props.raise("to_world", "flattens the cylinder (its transform is singular)");
    }
    area_ = float(profile_.perimeter());
  }

  BoundingBox3f bbox() const override { return toWorld_.bbox({Point3f(-1, -1, 0), Point3f(1, 1, 1)}); }
  float surfaceArea() const override { return area_; }

  PositionSample samplePosition(const Point2f& u) const override {
    // z uniform and phi uniform by the cross-section's arc length: uniform by
    // area (on a circular tube phi is simply 2 pi u.y).
    float phi = float(profile_.angleAtFraction(u.y));
    Point3f local(std::cos(phi), std::sin(phi), u.x);
    PositionSample ps;
    ps.p = toWorld_.point(local);
    ps.n = normalAt(local);
    ps.uv = Point2f(phi * Inv2Pi, u.x);
    ps.pdf = 1.0f / area_;
    return ps;
  }

  /// Quadratic in object space, in double, with the discriminant from the
  /// distance of the axis to the ray's line (Haines et al., Ray Tracing Gems
  /// ch. 7, as for the sphere, here in the xy plane) and the stable root
  /// formula. The nearer root is skipped when it lies beyond an open end.
  bool intersect(const Ray& ray, float& t, Point2f& uv) const override {
    Ray local = toLocal_.ray(ray);
    double ox = local.o.x, oy = local.o.y, dx = local.d.x, dy = local.d.y;
    double a = dx * dx + dy * dy;
    if (a == 0.0) return false;  // parallel to the axis
    double b = -(ox * dx + oy * dy);
    double lx = ox + dx * (b / a), ly = oy + dy * (b / a);  // closest point of the line to the axis
    double discriminant = a * (1.0 - (lx * lx + ly * ly));
    if (discriminant < 0.0) return false;
    double c = ox * ox + oy * oy - 1.0;
    double q = b + std::copysign(std::sqrt(discriminant), b);
    double roots[2] = {c / q, q / a};
    if (q == 0.0) roots[0] = roots[1] = 0.0;
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    for (double tHit : roots) {
      if (!(tHit > ray.tmin && tHit < ray.tmax)) continue;
      double z = double(local.o.z) + tHit * double(local.d.z);
      if (z < 0.0 || z > 1.0) continue;
      t = float(tHit);
      uv = Point2f(0.0f, 0.0f);  // recomputed from the hit point
      return true;
    }
    return false;
  }

  void computeInteraction(const Ray& ray, float t, uint32_t, const Point2f&, SurfaceInteraction& si) const override {
    // Project the object-space hit back onto the unit tube (removes the error of o + t d).
    Point3f local = toLocal_.point(ray(t));
    float r = std::sqrt(local.x * local.x + local.y * local.y);
    if (r > 0.0f) local.x /= r, local.y /= r;
    local.z = std::clamp(local.z, 0.0f, 1.0f);
    si.p = toWorld_.point(local);
    si.n = normalAt(local);
    si.sh = Frame(si.n);
    float phi = std::atan2(local.y, local.x);
    if (phi < 0.0f) phi += 2.0f * Pi;
    si.uv = Point2f(phi * Inv2Pi, local.z);
  }

  std::string toString() const override {
    return str("Cylinder[area=", area_, ", flip_normals=", flipNormals_ ? "true" : "false", "]");
  }

 private:
  Normal3f normalAt(const Point3f& local) const {
    Normal3f n = normalize(toWorld_.normal(Normal3f(local.x, local.y, 0.0f)));
    return flipNormals_ ? -n : n;
  }

  Transform toWorld_, toLocal_;
  EllipseArc profile_;  // the cross-section, whose arc length is the area per unit height fraction
  float area_ = 0.0f;
  bool flipNormals_ = false;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::Cylinder, Shape, "cylinder", "Analytic open cylinder")
