#pragma once
// How soon light at a point can still reach the film: with observer time,
// every camera path ends at the camera, so light at x with OPL tau arrives
// no earlier than tau + (distance from x to the nearest ray origin); eta >= 1
// everywhere, and later segments only add. The photon pass uses it to stop
// photons and end beams that cannot land in the film's window (issue 34's
// time gating for beams; docs/design/photon-beams.md, "Photons past the
// window").
#include <femto/math/vector.h>

namespace femto {
class Scene;
}

namespace femto::beams {

/// A ball holding every camera ray's origin (a projective camera's centre,
/// or its lens); `valid` false (no bound) for other sensors, and without
/// observer time.
struct CameraReach {
  Point3f center{0.0f};
  float radius = 0.0f;
  bool valid = false;

  /// A lower bound of the length of any path from x to a camera ray's origin.
  float distance(const Point3f& x) const {
    return valid ? std::max(0.0f, femto::distance(x, center) - radius) : 0.0f;
  }
};

CameraReach cameraReach(const Scene& scene, bool observerTime);

/// The smallest s in [0, length] at which light at origin + s dir, of OPL
/// opl + eta s, can no longer reach the film before `limit` (opl + eta s +
/// reach.distance(.) >= limit, non-decreasing in s as eta >= 1); `length`
/// when it can all along.
float reachableLength(const CameraReach& reach, const Point3f& origin, const Vec3f& dir, float length, double opl,
                      float eta, double limit);

}  // namespace femto::beams
