#pragma once
// The kernel's boundary loss measured on the scene (docs/design/photon-beams.md,
// "The boundary loss counted on the scene"). boundaryRadius (radius_rule.h)
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

/// The share of the kernel's reach about `x` (in `medium`) that no beam
/// along unit `direction` crosses: points that a straight path from x
/// leaves the medium to get to, unless a line along +-direction through
/// them meets a boundary of the medium within the extension there
/// (boundaryExtension r). The reach is the segment [-r, r] along unit
/// `across` (the 1D kernel's offsets, across = w x v / |w x v|), or, with
/// `across` zero, the disc of radius r across `direction` (the cylinder
/// kernel). DiscPoints points, shifted by `turn` in [0, 1). Deterministic.
double uncoveredShare(const Scene& scene, const Point3f& x, const Vec3f& direction, const Vec3f& across,
                      const Medium* medium, double r, double turn);

/// A camera point where beams meet a probe, a beam direction there, the
/// direction the 1D kernel's offsets run (zero: the disc), and the share of
/// the estimate it stands for.
struct CoverageSample {
  Point3f x;
  Vec3f direction;
  Vec3f across;
  const Medium* medium;
  double weight;
  /// The reach at the sampling radius lies in the medium: nothing is lost
  /// at any radius up to that one.
  bool inside = false;
};

/// Samples of the pairs (at most MaxCoveragePairs, evenly) at radius r: a
/// pair the 1D kernel weighs gathers at its closest approach, one sample
/// there; a pair the cylinder weighs (its chord clipped) along its overlap,
/// PointsPerPair samples. Each weighs the ideal estimate it stands for,
/// pairContribution / (1 - f), f the uncovered share at r: where f of the
/// reach holds no beams, 1 - f of the pairs are found.
std::vector<CoverageSample> coverageSamples(const Scene& scene, const std::vector<NearPair>& pairs, double r);

/// The estimate's relative loss at boundaries at radius r (at most the
/// samples' radius): sum w f / sum w over the samples, f the uncovered
/// share at r, capped at MaxUncovered. 0 without samples.
double boundaryLossShare(const Scene& scene, const std::vector<CoverageSample>& samples, double r);

/// Largest radius <= `sampled` at which the loss counted on `samples`
/// (drawn at `sampled`) stays within BoundaryBiasTarget: +Infinity when it
/// does at `sampled`, else the radius where the loss crosses the target,
/// within a factor 1.04 below (the loss grows at least linearly in r: first
/// order at planar boundaries, r^(3/2) where curvature leaves lines
/// uncovered). Deterministic.
double radiusWithinTarget(const Scene& scene, const std::vector<CoverageSample>& samples, double sampled);

/// The boundary bound: radiusWithinTarget on samples drawn at `upper`, then
/// again on samples drawn at the radius found (the smaller of the two).
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

/// Points per reach (segment or disc): 16 resolve a share of 1/32.
constexpr int DiscPoints = 16;
/// Pairs sampled, and samples per cylinder pair (each about DiscPoints
/// short ray casts at the sampling radius; samples whose reach leaves the
/// medium there, again per radius tried). The loss sits in the few pairs
/// beside a boundary, and its count is as noisy as they are few: on random
/// media seed 21 at r = 0.06, 1024 pairs counted 0.59-0.88 %, 16384 pairs
/// 1.0-1.6 %, 65536 pairs 1.2-1.4 % (measured: 1.0-1.1 %).
constexpr size_t MaxCoveragePairs = 16384;
constexpr int PointsPerPair = 4;
/// Probe x beam distance evaluations that find the pairs (nearPairs, with
/// its line test; with the above, the fog box's 32 x 32 render takes 0.02
/// CPU s more than with 1024 pairs found in 2^20 evaluations).
constexpr size_t MaxCoverageDistancePairs = size_t(1) << 22;
/// A disc at most this far uncovered counts 1 / (1 - f) (above).
constexpr double MaxUncovered = 0.9;

}  // namespace femto::beams
