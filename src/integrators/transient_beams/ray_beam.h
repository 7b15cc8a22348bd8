#pragma once
// Ray x beam density estimation with a 1D kernel, made transient.
//
// Steady estimate (Jarosz et al. 2011, eq. 27, "beam x beam 1D"): a camera
// segment passing at distance d < r from a beam receives
//
//   L += sigma_s(x_c) f_p(-ray.d, -beam.d) T_cam(t_c) T_beam(t_b) Phi / (2 r sin(theta))
//
// evaluated where the two lines come closest (x_c = ray(t_c), beam point at t_b),
// theta the angle between them.
//
// Transient (Marco et al. 2017, sec. 4): the part of the camera segment
// inside the beam's kernel region maps to a continuous interval of arrival
// OPLs -- camera OPL to the point plus the beam's OPL to its projection --
// and the estimate is spread uniformly over that interval (the film's
// addInterval deposits it exactly per bin). Along the overlap the total OPL
// changes at a rate eta*(1 + cos(theta')) per unit length on the camera ray
// (theta' between beam direction and the reversed camera direction): an
// anti-parallel pair collapses to one instant, a parallel pair spreads widest.
//
// Hard cases the implementation must survive (each has a unit test against a
// numerically integrated reference): near-parallel and anti-parallel pairs,
// grazing angles, beams starting or ending inside the kernel, zero-length
// overlaps. The returned kernel factor and OPLs are always finite.
#include <transient_beams/beam.h>

namespace femto::beams {

/// One camera segment x beam pair within the kernel radius.
struct RayBeamHit {
  float tRay = 0.0f;    // camera parameter where sigma_s, f_p and T_cam are evaluated
  float tBeam = 0.0f;   // beam parameter where T_beam is evaluated (0 <= tBeam <= length)
  float kernel = 0.0f;  // geometric density factor (1 / (2 r sin(theta)) away from the hard cases); finite, >= 0
  /// OPL added to (camera OPL at ray.o) + beam.opl at the two ends of the
  /// overlap: the estimate covers [oplBegin, oplEnd], oplBegin <= oplEnd
  /// (equal when the interval collapses).
  double oplBegin = 0.0, oplEnd = 0.0;
};

/// Does `segment` pass within `radius` of `beam`? On true, `hit` holds the
/// estimate's geometry; false leaves `hit` unspecified.
bool rayBeamIntersect(const CameraSegment& segment, const Beam& beam, float radius, RayBeamHit& hit);

}  // namespace femto::beams
