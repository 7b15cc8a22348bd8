#pragma once
// The share of a surface photon kernel's disc that lies on the gathering
// point's surface. A disc reaching past the surface's edge (a wall meeting
// the floor, the rim of a box) finds no photons beyond it: the density
// estimate divided by the whole disc's area is low there by the share off
// the surface (half the disc on the edge, 2 / (3 pi) of it averaged over the
// band of width r beside a straight edge; docs/design/photon-beams.md, "The surface
// radius"). The camera side divides by the covered area instead.
#include <femto/math/vector.h>

namespace femto {
class Scene;
}

namespace femto::beams {

/// Points of the disc coveredShare tests, on one ring of radius 2r/3. Beside
/// a straight edge at distance d < rho the ring loses the share
/// acos(d / rho) / pi of its points; averaged over the band d in [0, r] that
/// is rho / (pi r), and the disc's own loss averaged so is 2 / (3 pi): the
/// two agree at rho = 2r/3 (for edges of any direction; against the 8 fixed
/// points an edge along the ring's frame reads 2.6 % more). At r / sqrt(2),
/// the ring halving the disc's area, it read 6 % more (measured: the
/// fog box's walls alone +0.4 % in the window sum).
constexpr int CoveragePoints = 8;

/// Share of the disc of radius r about `p` (on a surface, unit normal `n` on
/// the side gathered) in the tangent plane that lies on a surface: a point
/// counts when a ray from p to it, lifted by a tenth of r along n, meets no
/// surface (a wall meeting this one) and a ray from there down -n meets one
/// within 1.5 r (none past a convex edge; a sphere of radius R >= r curves
/// away by at most 0.26 R below the ring, within reach: the photons' ball
/// meets it in a cap of area pi r^2, all covered; on a sphere smaller than
/// the kernel the ring falls off it and the share undercounts the cap).
/// Index-matched boundaries (media) are passed through. In [0, 1];
/// deterministic.
double coveredShare(const Scene& scene, const Point3f& p, const Vec3f& n, double r);

/// The smallest share the camera side divides by (a quarter: the disc at a
/// corner where three walls meet): below it a gather point is a spike or a
/// slit the ring resolves poorly.
constexpr double MinCoveredShare = 0.25;

}  // namespace femto::beams
