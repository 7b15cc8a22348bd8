// Ray x photon point 2D-kernel estimate, transient (see ray_point.h and
// docs/design/photon-beams.md, "Photon points vs photon beams").
#include <transient_beams/ray_point.h>

#include <cmath>

#include <femto/math/constants.h>

namespace femto::beams {

bool rayPointIntersect(const CameraSegment& segment, const Beam& point, float radius, RayBeamHit& hit) {
  const float r2 = radius * radius, tMax = segment.tMax;
  // Degenerate input: no kernel region or no segment (NaN fails every test).
  if (!(radius > 0.0f) || !(r2 > 0.0f) || !(radius < Infinity) || !(tMax > 0.0f)) return false;
  // A direction that is not unit (zero, NaN) would project every photon to 0.
  const float unit = dot(segment.ray.d, segment.ray.d);
  if (!(unit > 0.5f && unit < 2.0f)) return false;
  const Vec3f delta = point.origin - segment.ray.o;
  const float t = dot(delta, segment.ray.d);  // projection on the (unit) camera direction
  if (!(t >= 0.0f && t <= tMax)) return false;
  // Squared distance to the camera ray's line as |delta x d|^2 (unit d): no
  // cancellation of |delta|^2 - t^2 for photons far along the ray.
  const Vec3f m = cross(delta, segment.ray.d);
  if (!(dot(m, m) < r2)) return false;
  hit.tRay = hit.tRayBegin = hit.tRayEnd = t;
  hit.tBeam = 0.0f;
  hit.kernel = InvPi / r2;
  // The gap from the photon to ray(t) is crossed at the photon's medium's
  // eta: the instant is then the OPL of a real path photon -> ray(t) ->
  // ray.o, never earlier than light could arrive (docs/design/photon-beams.md,
  // "Causality").
  const double gap = std::sqrt(double(dot(m, m)));
  hit.oplBegin = hit.oplEnd = double(segment.eta) * double(t) + double(point.eta) * gap;
  // Last line of defence: nothing non-finite reaches the film.
  return hit.kernel > 0.0f && std::isfinite(hit.kernel) && std::isfinite(hit.oplBegin);
}

}  // namespace femto::beams
