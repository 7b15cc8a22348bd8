#pragma once
// The kernel's boundary loss measured on the scene (docs/photon-beams.md,
// "The boundary loss measured on the scene"). boundaryRadius (radius_rule.h)
// bounds the loss the extensions leave with a planar model: BoundaryLossLeft
// of the first-order loss, the grazing beams' share for isotropic beams.
// Where the boundary curves, lines beside a beam that touches it miss the
// medium altogether, and no extension (boundary_extension.h) stands for
// them: near a convex medium's terminator (light from outside, beams
// tangent to the boundary) a camera point's disc loses up to half its area
// at every depth below r. Random media seed 23 (a sphere lit from outside)
// read -1.2 % at the planar radius, against the 0.4 % the rule promises.
// Here the loss is counted instead: at each probe x beam pair's camera
// point x, the share of the kernel's disc (across the beam) that no beam of
// the pair's direction can cross, being neither in x's medium nor on an
// extension of a beam entering or leaving it within reach.
#include <vector>

#include <femto/math/vector.h>

#include <transient_beams/radius_rule.h>

namespace femto {
class Scene;
class Medium;
}  // namespace femto

namespace femto::beams {

/// The share of the disc of radius r across unit `direction` about `x` (in
/// `medium`) that no beam along `direction` reaches: points that a straight
/// path from x leaves the medium to get to, unless a line along
/// +-direction through them meets a boundary of the medium within the
/// extension there (boundaryExtension r). DiscPoints points, rotated by
/// `turn` (a fraction of a turn). Deterministic.
double uncoveredShare(const Scene& scene, const Point3f& x, const Vec3f& direction, const Medium* medium, double r,
                      double turn);

/// A camera point where beams meet a probe, a beam direction there, and the
/// share of the estimate it stands for.
struct CoverageSample {
  Point3f x;
  Vec3f direction;
  const Medium* medium;
  double weight;
};

/// PointsPerPair samples along the overlap of each pair (at most
/// MaxCoveragePairs, evenly) at radius r, weighted by pairContribution.
std::vector<CoverageSample> coverageSamples(const std::vector<NearPair>& pairs, double r);

/// The estimate's relative loss at boundaries at radius r: with f the
/// uncovered share at each sample, sum w f / (1 - f) / (sum w + sum w f /
/// (1 - f)) (beams are found where 1 - f of the disc holds them; f capped
/// at MaxUncovered). 0 without samples.
double boundaryLossShare(const Scene& scene, const std::vector<CoverageSample>& samples, double r);

/// Largest radius <= upper whose measured loss stays within
/// BoundaryBiasTarget: +Infinity when `upper` keeps it (or nothing gives
/// pairs), else the radius where the loss crosses the target, within a
/// factor 1.04 below (the loss grows at least linearly in r: first order at
/// planar boundaries, r^(3/2) where curvature leaves lines uncovered).
/// The camera points and directions are sampled once, at `upper`.
/// Deterministic.
double coveredBoundaryRadius(const Scene& scene, const std::vector<Beam>& beams,
                             const std::vector<ProbeSegment>& probes, double upper);

/// What the counted bound needs beyond the beams: the scene to cast rays in
/// and probes through a CoverageProbeGrid^2 grid of the film. The 8 x 8
/// probes of the density bound miss the view's silhouettes of a medium,
/// where camera segments graze its boundary and lie within r of it all
/// along: on seed 23 (an 8 x 8 film, probes at the pixel centres) the loss
/// counted on them was half the render's.
struct SceneCoverage {
  const Scene& scene;
  std::vector<ProbeSegment> probes;
};
constexpr int CoverageProbeGrid = 32;

/// Disc points per pair: 16 resolve a share of 1/32.
constexpr int DiscPoints = 16;
/// Pairs whose overlaps are sampled, and points per pair (each about
/// DiscPoints short ray casts per radius tried).
constexpr size_t MaxCoveragePairs = 1024;
constexpr int PointsPerPair = 4;
/// A disc at most this far uncovered counts 1 / (1 - f) (above).
constexpr double MaxUncovered = 0.9;

}  // namespace femto::beams
