// Perspective pinhole camera (Mitsuba's `perspective`). Camera space as in
// Mitsuba: the camera looks along +z, +y is up and +x points to the LEFT of
// the image; film position (0, 0) is the top-left corner of the full film
// (crop windows need no special care, since film positions are full-film).
//
// | name        | type      | default  | meaning                                                      |
// |-------------|-----------|----------|--------------------------------------------------------------|
// | to_world    | transform | identity | camera-to-world transform                                    |
// | medium      | medium    | none     | the medium the camera sits in: a nested <medium> or <ref>, any name |
// | fov         | float     | —        | field of view in degrees, in (0, 180), along `fov_axis`      |
// | fov_axis    | string    | "x"      | x, y, diagonal, smaller or larger: the axis `fov` spans      |
// | focal_length| string    | "50mm"   | 35 mm-equivalent focal length (instead of fov; spans the diagonal) |
// | near_clip   | float     | 0.01     | distance (scene units) before which nothing is seen          |
// | far_clip    | float     | 10000    | distance beyond which nothing is seen                        |
// | focus_distance | float  | far_clip | accepted for Mitsuba scenes; a pinhole is in focus everywhere |
// | principal_point_offset_x | float | 0 | shift of the image plane, in film widths (Mitsuba 3)    |
// | principal_point_offset_y | float | 0 | shift of the image plane, in film heights (Mitsuba 3)   |
// | srf         | spectrum  | —        | Mitsuba 3's sensor response: refused (femto renders RGB)     |
//
// Principal point offsets follow Mitsuba 3's perspective.cpp (sample_ray):
// the offset is added to the film position in film-size units, so pixel
// (sx, sy) sees what the centred camera sees at (sx + offset_x, sy + offset_y)
// ("the position of the camera's principal point relative to the center of
// the film", Mitsuba 3 docs, sensor-perspective). A positive offset_x therefore
// turns the view to the image right, a positive offset_y down; the centre of
// projection stays at the camera origin (an off-axis frustum, not a rotation).
// fov_axis is case-insensitive, as in Mitsuba.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <femto/core/plugin.h>
#include <femto/render/sensor.h>

namespace femto {

class PerspectiveCamera final : public Sensor {
 public:
  explicit PerspectiveCamera(const Properties& props) : Sensor(props) {
    nearClip_ = props.getFloat("near_clip", 0.01f, Range::positive());
    farClip_ = props.getFloat("far_clip", 10000.0f);
    if (!(farClip_ > nearClip_)) props.raise("far_clip", str("must be larger than near_clip (", nearClip_, ")"));
    // Mitsuba's projective cameras all take a focus distance; only thinlens uses it.
    props.getFloat("focus_distance", farClip_, Range::positive());
    offset_.x = props.getFloat("principal_point_offset_x", 0.0f, Range::finite());
    offset_.y = props.getFloat("principal_point_offset_y", 0.0f, Range::finite());
    if (props.has("srf"))
      props.raise("srf", "spectral sensor response functions are not supported (femto renders RGB)");

    const Point2i size = film_->size();
    const float width = float(size.x), height = float(size.y);
    float tanHalf;
    std::string axis;
    if (props.has("fov")) {
      if (props.has("focal_length")) props.raise("focal_length", "give either \"fov\" or \"focal_length\", not both");
      fov_ = props.getFloatIn("fov", Range::open(0, 180), "degrees");
      tanHalf = std::tan(degToRad(fov_) * 0.5f);
      axis = lowercase(props.getString("fov_axis", "x"));
    } else {
      // 35 mm film is 36 x 24 mm: the focal length fixes the diagonal field of view.
      float focal = parseMillimetres(props, "focal_length", props.getString("focal_length", "50mm"));
      tanHalf = std::sqrt(36.0f * 36.0f + 24.0f * 24.0f) / (2.0f * focal);
      fov_ = radToDeg(2.0f * std::atan(tanHalf));
      axis = "diagonal";
      if (props.has("fov_axis")) props.getString("fov_axis");  // meaningless with a focal length; accepted
    }
    // Half-extents of the image plane at z = 1 along x and y.
    if (axis == "smaller") axis = width <= height ? "x" : "y";
    if (axis == "larger") axis = width >= height ? "x" : "y";
    if (axis == "x") {
      tanX_ = tanHalf;
      tanY_ = tanHalf * height / width;
    } else if (axis == "y") {
      tanY_ = tanHalf;
      tanX_ = tanHalf * width / height;
    } else if (axis == "diagonal") {
      float diagonal = std::sqrt(width * width + height * height);
      tanX_ = tanHalf * width / diagonal;
      tanY_ = tanHalf * height / diagonal;
    } else {
      props.raise("fov_axis", str("unknown axis \"", axis, "\" (expected x, y, diagonal, smaller or larger)"));
    }
  }

  Color3f sampleRay(const Point2f& filmPos, const Point2f&, Ray& ray) const override {
    const Point2i size = film_->size();
    // Film (0, 0) is top-left; camera +x is left and +y up. The principal
    // point offset shifts the film position in film-size units (Mitsuba 3).
    float sx = filmPos.x / float(size.x) + offset_.x, sy = filmPos.y / float(size.y) + offset_.y;
    Vec3f dCamera((1.0f - 2.0f * sx) * tanX_, (1.0f - 2.0f * sy) * tanY_, 1.0f);
    Vec3f dWorld = toWorld_.vector(dCamera);
    // The clip planes are z = near/far in camera space: distances along the
    // unit world ray are the clip values times the length of dWorld.
    float len = length(dWorld);
    ray = Ray(toWorld_.point(Point3f(0.0f)), dWorld / len, nearClip_ * len, farClip_ * len);
    return Color3f(1.0f);
  }

  std::string toString() const override {
    return str("PerspectiveCamera[fov=", fov_, ", near_clip=", nearClip_, ", far_clip=", farClip_,
               ", principal_point_offset=", offset_, "]");
  }

 private:
  static std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
  }

  static float parseMillimetres(const Properties& props, const std::string& name, const std::string& text) {
    size_t used = 0;
    float value = 0.0f;
    try {
      value = std::stof(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    std::string unit = text.substr(used);
    if (used == 0 || (unit != "mm" && !unit.empty()) || !(value > 0.0f))
      props.raise(name, str("expected a length such as \"50mm\", got \"", text, "\""));
    return value;
  }

  float fov_ = 0.0f, tanX_ = 0.0f, tanY_ = 0.0f;
  Point2f offset_;  // principal point offset, in film widths and heights
  float nearClip_, farClip_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::PerspectiveCamera, Sensor, "perspective", "perspective pinhole camera")
