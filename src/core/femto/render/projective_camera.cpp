#include <femto/render/projective_camera.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <femto/math/constants.h>

namespace femto {
namespace {

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

float parseMillimetres(const Properties& props, const std::string& name, const std::string& text) {
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

}  // namespace

ProjectiveCamera::ProjectiveCamera(const Properties& props, float defaultFocus) : Sensor(props) {
  nearClip_ = props.getFloat("near_clip", 0.01f, Range::positive());
  farClip_ = props.getFloat("far_clip", 10000.0f);
  if (!(farClip_ > nearClip_)) props.raise("far_clip", str("must be larger than near_clip (", nearClip_, ")"));
  focusDistance_ = props.getFloat("focus_distance", defaultFocus < 0.0f ? farClip_ : defaultFocus, Range::positive());
  offset_.x = props.getFloat("principal_point_offset_x", 0.0f, Range::finite());
  offset_.y = props.getFloat("principal_point_offset_y", 0.0f, Range::finite());
  if (props.has("srf")) props.raise("srf", "spectral sensor response functions are not supported (femto renders RGB)");

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

}  // namespace femto
