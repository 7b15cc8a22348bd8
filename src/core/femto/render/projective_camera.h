#pragma once
// What Mitsuba's projective cameras (perspective, thinlens) share: the field
// of view (fov + fov_axis, or a 35 mm focal_length), near and far clip
// planes, the focus distance and Mitsuba 3's principal point offset, read
// once, and the camera-space direction through a film position.
//
// Camera space as in Mitsuba: the camera looks along +z, +y is up and +x
// points to the LEFT of the image; film position (0, 0) is the top-left
// corner of the full film. Principal point offsets follow Mitsuba 3's
// perspective.cpp (sample_ray): the offset is added to the film position in
// film-size units, so pixel (sx, sy) sees what the centred camera sees at
// (sx + offset_x, sy + offset_y); a positive offset_x turns the view to the
// image right, a positive offset_y down (an off-axis frustum, not a rotation).
#include <femto/math/vector.h>
#include <femto/render/sensor.h>

namespace femto {

class ProjectiveCamera : public Sensor {
 public:
  float fov() const { return fov_; }
  float nearClip() const { return nearClip_; }
  float farClip() const { return farClip_; }
  float focusDistance() const { return focusDistance_; }
  const Point2f& principalPointOffset() const { return offset_; }

 protected:
  /// Reads the parameters above; `defaultFocus` < 0 means far_clip (Mitsuba's
  /// default for cameras whose focus does not matter).
  ProjectiveCamera(const Properties& props, float defaultFocus);

  /// Camera-space direction through continuous film position `filmPos`
  /// (pixels of the full film), on the plane z = 1 (not normalised).
  Vec3f cameraDirection(const Point2f& filmPos) const {
    const Point2i size = film_->size();
    float sx = filmPos.x / float(size.x) + offset_.x, sy = filmPos.y / float(size.y) + offset_.y;
    return Vec3f((1.0f - 2.0f * sx) * tanX_, (1.0f - 2.0f * sy) * tanY_, 1.0f);
  }

 private:
  float fov_ = 0.0f, tanX_ = 0.0f, tanY_ = 0.0f;
  Point2f offset_;  // principal point offset, in film widths and heights
  float nearClip_ = 0.01f, farClip_ = 10000.0f, focusDistance_ = 0.0f;
};

}  // namespace femto
