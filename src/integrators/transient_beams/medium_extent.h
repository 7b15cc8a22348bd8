#pragma once
// Where media are, for the two tracers of transient_beams: the medium a point
// light's photons start in when the emitter names none, and how long a beam or
// camera segment that meets no surface needs to be.
#include <femto/math/ray.h>

namespace femto {
class Medium;
class Scene;
}  // namespace femto

namespace femto::beams {

/// The medium around `ray.o`, found by following the ray to the first surface
/// that bounds a medium and taking the medium on the side the ray came from
/// (surfaces bounding none are skipped). A ray that meets no such surface is
/// in the sensor's medium (Mitsuba's convention for unbounded media).
const Medium* mediumAround(const Scene& scene, const Ray& ray);

/// Length of a segment in `medium` starting at OPL `opl` that meets no surface
/// (tHit = Infinity): far enough that what lies beyond cannot matter -- its
/// OPL passes `horizon`, or (homogeneous media) its transmittance falls below
/// e^-40. 0 when neither bound exists (the segment is dropped).
float unboundedSegmentLength(const Medium& medium, double opl, double horizon);

}  // namespace femto::beams
