// Orthographic camera (Mitsuba's `orthographic`): parallel rays along the
// camera's +z axis. In camera space the film covers x in [-1, 1] and
// y in [-1/a, 1/a] (a = width / height) of the plane z = 0, as in Mitsuba:
// scale `to_world` to change the size of the view. As with `perspective`,
// camera +x is the LEFT of the image and film (0, 0) its top-left corner.
// Rays start on the plane z = 0; the clip distances are camera-space z.
//
// | name      | type      | default  | meaning                                         |
// |-----------|-----------|----------|-------------------------------------------------|
// | to_world  | transform | identity | camera-to-world transform (its scale sets the view size) |
// | medium      | medium    | none     | the medium the camera sits in: a nested <medium> or <ref>, any name |
// | near_clip | float     | 0.01     | camera-space depth before which nothing is seen |
// | far_clip  | float     | 10000    | camera-space depth beyond which nothing is seen |
#include <femto/core/plugin.h>
#include <femto/render/sensor.h>

namespace femto {

class OrthographicCamera final : public Sensor {
 public:
  explicit OrthographicCamera(const Properties& props) : Sensor(props) {
    nearClip_ = props.getFloat("near_clip", 0.01f, Range::nonNegative());
    farClip_ = props.getFloat("far_clip", 10000.0f);
    if (!(farClip_ > nearClip_)) props.raise("far_clip", str("must be larger than near_clip (", nearClip_, ")"));
    // Mitsuba's projective cameras all take a focus distance; an orthographic camera has no lens.
    props.getFloat("focus_distance", farClip_);
    Vec3f axis = toWorld_.vector(Vec3f(0.0f, 0.0f, 1.0f));
    axisLength_ = length(axis);
    if (!(axisLength_ > 0.0f)) props.raise("to_world", "maps the viewing direction to zero");
    direction_ = axis / axisLength_;
    aspect_ = float(film_->size().x) / float(film_->size().y);
  }

  Color3f sampleRay(const Point2f& filmPos, const Point2f&, Ray& ray) const override {
    const Point2i size = film_->size();
    float sx = filmPos.x / float(size.x), sy = filmPos.y / float(size.y);
    Point3f onPlane(1.0f - 2.0f * sx, (1.0f - 2.0f * sy) / aspect_, 0.0f);
    // Distances along the unit world ray are camera-space depths times the axis' length.
    ray = Ray(toWorld_.point(onPlane), direction_, nearClip_ * axisLength_, farClip_ * axisLength_);
    return Color3f(1.0f);
  }

  std::string toString() const override {
    return str("OrthographicCamera[near_clip=", nearClip_, ", far_clip=", farClip_, "]");
  }

 private:
  float nearClip_, farClip_, axisLength_ = 1.0f, aspect_ = 1.0f;
  Vec3f direction_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::OrthographicCamera, Sensor, "orthographic", "orthographic (parallel projection) camera")
