#pragma once
// Ray x photon point density estimation with a 2D kernel, made transient: the
// comparison estimator of transient_beams (volume_estimator = "points").
//
// Steady estimate: the "beam radiance estimate" of Jarosz, Zwicker, Jensen
// 2008 ("The Beam Radiance Estimate for Volumetric Photon Mapping"), called
// "point x beam (2D)" in Jarosz, Nowrouzezahrai, Sadeghi, Jensen 2011 (the
// camera ray is the "beam" query, the photons are points). Photons stored at
// their scattering vertices x_i inside a medium, each blurred by the disc
// kernel K2 = 1/(pi r^2) in the plane perpendicular to the camera segment,
// give the in-scattered radiance accumulated along the segment
//
//   L += sum_i sigma_s(x_i) f_p(-ray.d, -w_i) T_cam(t_i) Phi_i K2,   |x_i - ray(t_i)| < r, 0 <= t_i <= tMax,
//
// with t_i the projection of x_i on the camera ray and w_i the direction the
// photon arrived from. Phi_i is the photon's flux at x_i *in beam units*: the
// photon tracer stores, at a free-flight event sampled with pdf p(t), the
// power arriving there times T(t)/p(t) (MediumSample::weight / sigma_s), so
// that sum_i Phi_i delta(x - x_i) has the expectation sum_beams Phi_b T_b(s)
// delta_line -- exactly the density the beams estimate (ray_beam.h). The two
// estimators then share one formula and one deposit (camera_tracer.cpp):
//
//   value = sigma_s(ray(tRay)) f_p T_cam(tRay) [T_beam(tBeam)] Phi kernel / N,
//
// the beam transmittance T_beam being 1 for a point (tBeam = 0: the photon's
// own free flight sampled it).
//
// Time: the disc kernel has no extent along the camera ray, so a pair is one
// instant: the photon's OPL, the gap from x_i to ray(t_i) (< r, crossed at
// the photon medium's eta) and the camera OPL to t_i (oplBegin = oplEnd =
// segment.eta t_i + point.eta gap): the OPL of a real path, so never before
// light could arrive; the time blur is below r eta and vanishes with the radius.
//
// Hard cases (tests/unit/integrators/transient_beams/test_ray_point.cpp): a photon exactly on the ray
// (distance 0), at either end of the segment (t_i = 0 or tMax, kept: the
// kernel region is the closed cylinder; its ends have measure zero), an
// unbounded segment (tMax = +inf), degenerate or non-finite input (false).
#include <transient_beams/beam.h>
#include <transient_beams/ray_beam.h>

namespace femto::beams {

/// Does `point` (a zero-length Beam: origin x_i, direction w_i, power Phi_i)
/// lie within `radius` of `segment`, its projection on [0, tMax]? On true
/// `hit` holds the estimate's geometry in the ray x beam form: tRay the
/// projection, tRayBegin = tRayEnd = tRay, tBeam = 0, kernel 1/(pi r^2),
/// oplBegin = oplEnd = segment.eta tRay + point.eta gap; every field finite. Non-finite or
/// degenerate input (radius not > 0, tMax not > 0, NaN anywhere) gives false.
bool rayPointIntersect(const CameraSegment& segment, const Beam& point, float radius, RayBeamHit& hit);

}  // namespace femto::beams
