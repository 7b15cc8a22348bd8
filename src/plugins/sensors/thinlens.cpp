// Perspective camera with a thin lens (Mitsuba's `thinlens`): depth of field.
// Rays leave a uniformly sampled point of the aperture disk (radius
// aperture_radius, in the camera's z = 0 plane) toward the point of the
// focal plane z = focus_distance that the pinhole ray through the same film
// position reaches, so everything at the focus distance is sharp. The
// time of arrival starts at the aperture point, as for a real lens
// (differences across the aperture are of order aperture_radius^2 / focus_distance).
//
// | name            | type      | default  | meaning                                                 |
// |-----------------|-----------|----------|---------------------------------------------------------|
// | aperture_radius | float     | required | radius of the aperture, scene units (>= 0; 0 = pinhole) |
// | focus_distance  | float     | far_clip | distance of the plane in focus, along the view axis     |
// | to_world, medium, fov, fov_axis, focal_length, near_clip, far_clip, principal_point_offset_x/y, srf | | | as `perspective` (render/projective_camera.h) |
#include <femto/core/plugin.h>
#include <femto/math/warp.h>
#include <femto/render/projective_camera.h>

namespace femto {

class ThinLensCamera final : public ProjectiveCamera {
 public:
  explicit ThinLensCamera(const Properties& props)
      : ProjectiveCamera(props, -1.0f), apertureRadius_(props.getFloatIn("aperture_radius", Range::nonNegative())) {}

  /// Mitsuba 3's thin-lens sample_ray: film position -> point on the focal
  /// plane; aperture sample -> point on the lens; the ray joins them. The
  /// clip planes stay planes of camera space (distances scaled by 1 / d.z).
  Color3f sampleRay(const Point2f& filmPos, const Point2f& u, Ray& ray) const override {
    Vec3f pinhole = cameraDirection(filmPos);  // on z = 1
    Point3f focus(pinhole.x * focusDistance(), pinhole.y * focusDistance(), focusDistance());
    Point2f lens = warp::squareToUniformDiskConcentric(u);
    Point3f aperture(lens.x * apertureRadius_, lens.y * apertureRadius_, 0.0f);
    Vec3f d = normalize(focus - aperture);
    Vec3f dWorld = toWorld_.vector(d);
    float len = length(dWorld);
    float invZ = 1.0f / d.z;
    ray = Ray(toWorld_.point(aperture), dWorld / len, nearClip() * invZ * len, farClip() * invZ * len);
    return Color3f(1.0f);
  }

  std::string toString() const override {
    return str("ThinLensCamera[fov=", fov(), ", aperture_radius=", apertureRadius_, ", focus_distance=", focusDistance(),
               ", near_clip=", nearClip(), ", far_clip=", farClip(), "]");
  }

 private:
  float apertureRadius_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ThinLensCamera, Sensor, "thinlens", "perspective camera with a thin lens (depth of field)")
