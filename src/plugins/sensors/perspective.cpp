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
// The parameters and the projection are ProjectiveCamera's
// (render/projective_camera.h), shared with thinlens; fov_axis is
// case-insensitive, as in Mitsuba.
#include <femto/core/plugin.h>
#include <femto/render/projective_camera.h>

namespace femto {

class PerspectiveCamera final : public ProjectiveCamera {
 public:
  // Mitsuba's projective cameras all take a focus distance; only thinlens uses it.
  explicit PerspectiveCamera(const Properties& props) : ProjectiveCamera(props, -1.0f) {}

  Color3f sampleRay(const Point2f& filmPos, const Point2f&, Ray& ray) const override {
    Vec3f dWorld = toWorld_.vector(cameraDirection(filmPos));
    // The clip planes are z = near/far in camera space: distances along the
    // unit world ray are the clip values times the length of dWorld.
    float len = length(dWorld);
    ray = Ray(toWorld_.point(Point3f(0.0f)), dWorld / len, nearClip() * len, farClip() * len);
    return Color3f(1.0f);
  }

  std::string toString() const override {
    return str("PerspectiveCamera[fov=", fov(), ", near_clip=", nearClip(), ", far_clip=", farClip(),
               ", principal_point_offset=", principalPointOffset(), "]");
  }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::PerspectiveCamera, Sensor, "perspective", "perspective pinhole camera")
