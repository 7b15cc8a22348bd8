#pragma once
// Directions from a vertex y toward a point c (a point light), for the
// light-directed next-event strategy of transient_path: the angle alpha
// between the direction and c - y is uniform on [0, pi/2) and the azimuth
// uniform, so the solid-angle density is
//   p(w) = 1 / (pi^2 sin alpha)   on the hemisphere facing c (0 elsewhere).
// Why: the single-scattered radiance from a point light arriving along a ray
// that passes at distance h = |c - y| sin alpha from it is ~ 1/h (the line
// integral of 1/r^2; equiangular sampling, transport/equiangular.h, estimates
// it exactly), so with directions from the phase function or BSDF, whose
// density stays bounded at alpha = 0, its second moment diverges (rays pass
// within h with probability ~ h^2: P(estimate > v) ~ v^-2, fireflies in the
// peer's fog Cornell box, issue 15). This density cancels the 1/h, bounding
// the estimate by ~ 1/|c - y|. It is the direction half of sampling the last
// medium vertex jointly with the light in mind (Georgiev et al., "Joint
// Importance Sampling of Low-Order Volumetric Scattering", SIGGRAPH Asia 2013).
#include <femto/math/vector.h>

namespace femto {

/// A direction from `y` for `u` in [0, 1)^2, with its solid-angle density;
/// pdf 0 when y sits on c.
Vec3f samplePointDirection(const Point3f& y, const Point3f& c, const Point2f& u, float& pdf);
/// Density of samplePointDirection choosing unit direction `w` from `y`.
float pdfPointDirection(const Point3f& y, const Point3f& c, const Vec3f& w);

}  // namespace femto
