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
// addInterval deposits it exactly per bin).
//
// Geometry (derivation and tests: docs/design/photon-beams.md). Camera segment
// x(t) = o + t w, t in [0, tMax]; beam y(s) = b + s v, s in [0, length];
// c = cos(theta) = w.v (w points away from the camera, v along the light).
//  * Kernel region: the finite cylinder of radius r around the beam, capped
//    by the planes through the beam's ends perpendicular to it. The segment's
//    overlap with it is [tRayBegin, tRayEnd] = chord of the infinite cylinder
//    (|x(t) - axis| < r, a quadratic in t) clipped to the slab
//    -before r <= s(t) = (x(t) - b).v <= length + after r (the beam's
//    extensions past boundaries, boundary_extension.h; 0 for most beams;
//    the one before the start is timed as the beam's continuation,
//    ray_beam.cpp) and to [0, tMax].
//  * OPL along the overlap: OPL(t) = segment.eta t + beam.eta s(t), linear in
//    t with rate segment.eta + beam.eta cos(theta). With equal indices a pair
//    whose beam travels toward the camera (w = -v, "anti-parallel") keeps the
//    path length stationary: the interval collapses to one instant; a beam
//    travelling away from the camera (w = v) spreads widest (rate 2 eta).
//  * Kernel value: the 1D estimate 1/(2 r sin(theta)) is an unbiased,
//    per-pair-constant stand-in for the exact blurred-beam integral
//    chord/(pi r^2) (averaged over the lateral offset d in [-r, r] the chord
//    2 sqrt(r^2 - d^2)/sin(theta) divided by pi r^2 gives exactly
//    1/(2 r sin(theta))) -- but only while the d = 0 chord, of half-length
//    r/sin(theta) around the closest approach, lies inside the slab and
//    [0, tMax]. Otherwise (near-parallel pairs, beam or camera segment ending
//    inside the kernel) the average no longer holds and 1/sin(theta) blows
//    up, so the pair gets the exact value chord/(pi r^2), finite (chord <=
//    min(tMax, length/|cos(theta)|)) and unbiased. The choice depends only on
//    quantities invariant under the lateral offset, so the mix stays unbiased.
//
// Hard cases (each has a unit test against a numerically integrated
// reference, tests/unit/integrators/transient_beams/test_ray_beam.cpp): near-parallel and anti-parallel
// pairs, grazing (tangent) passes, beams starting or ending inside the
// kernel, camera segments ending inside it, zero-length overlaps, degenerate
// and non-finite input. On true, every field of the hit is finite.
#include <cmath>

#include <transient_beams/beam.h>

#include <femto/math/vector.h>

namespace femto::beams {

/// Which kernel weights a pair (docs/design/photon-beams.md, "Kernel value").
enum class RayBeamKernel {
  /// Jarosz et al. 2011 beam x beam 1D, 1/(2 r sin(theta)), where the whole
  /// kernel chord fits in both segments; the exact cylinder value elsewhere.
  OneD,
  /// Always the exact line integral of the beam blurred by the disc kernel
  /// 1/(pi r^2): chord/(pi r^2). Its transient deposit equals the blurred
  /// beam's arrival-time density exactly, bin by bin (for comparison).
  Cylinder,
};

/// One camera segment x beam pair within the kernel radius. All fields finite.
struct RayBeamHit {
  float tRay = 0.0f;    // camera parameter where sigma_s, f_p and T_cam are evaluated (in [tRayBegin, tRayEnd])
  float tBeam = 0.0f;   // beam parameter where T_beam is evaluated (0 <= tBeam <= length): the projection of ray(tRay)
  float kernel = 0.0f;  // geometric density factor, 1/area (1 / (2 r sin(theta)) away from the hard cases); finite, > 0
  /// OPL added to (camera OPL at ray.o) + beam.opl at the two ends of the
  /// overlap: the estimate covers [oplBegin, oplEnd], oplBegin <= oplEnd
  /// (equal when the interval collapses).
  double oplBegin = 0.0, oplEnd = 0.0;
  /// The overlap on the camera segment: 0 <= tRayBegin < tRayEnd <= tMax.
  float tRayBegin = 0.0f, tRayEnd = 0.0f;
  /// The 1D kernel weighs the pair (OneD, the whole chord fits): the
  /// estimate gathers the beams at offsets along w x v from ray(tRay), not
  /// over the disc across the beam (boundary_coverage.h counts either).
  bool oneD = false;
};

/// The OPL a pair deposits at camera parameter t, relative to (camera OPL at
/// ray.o) + beam.opl: the causal timing rayBeamIntersect derives (ray_beam.cpp:
/// light at x(t) left the beam's start, or its extension's, and ran straight;
/// the tilted wavefront of a beam that entered through a boundary of another
/// index). Convex in t. Without observer time (segment.eta = 0) it is
/// stationary where the camera ray passes closest to that start: the pair's
/// arrival density there is an integrable (tau - tau_0)^(-1/2) peak, which a
/// deposit uniform between the overlap's end values misses (PairOpl::pieces).
struct PairOpl {
  PairOpl(const CameraSegment& segment, const Beam& beam, float radius, const RayBeamHit& hit);
  double operator()(float t) const;
  /// dOPL/dt (one-sided where the tilted wavefront takes over).
  double slope(float t) const;
  /// A part of the pair's deposit: `weight` of it spread uniformly over [begin, end].
  struct Piece {
    double begin = 0.0, end = 0.0, weight = 1.0;
  };
  /// The pair's deposit as pieces of the overlap, each spread uniformly
  /// between its ends' OPLs (chords of the convex OPL) and weighted by its
  /// share of the overlap's length: split at the stationary point, and cut
  /// evenly into as many as keep every chord within `tolerance` of the OPL
  /// it stands for (a chord over [a, b] lies at most (b - a)(g'(b) - g'(a)) / 4
  /// above a convex g), at most `maxPieces` (>= 2) in all. Returns the
  /// count written to `out`, or 1 with `out` untouched where one piece, the
  /// hit's [oplBegin, oplEnd], already holds: nearly every pair with
  /// observer time.
  int pieces(double tolerance, Piece* out, int maxPieces) const;

 private:
  float tBegin_, tEnd_;
  Vec3f fromStart_, w_, offsetDelay_;
  Vec3f delta_;
  double shift_, etaBeam_, etaCamera_, s0_, cosTheta_;
  bool onExtension_;
};

/// The beam map's cull (BeamMap::Cull::Lines): true only when the segment's
/// line passes the beam's axis farther than `radius`, so that the segment
/// misses the kernel region wherever its ends are. About half the work of
/// rayBeamIntersect's first test: the lines' distance is |delta . n| / |n|,
/// n = w x v (|n| = sin(theta)). Conservative against that test (it never
/// says true where that test keeps the pair): both err by a few float ulps of
/// |delta| in d sin(theta) (the cancellation in delta's part across the beam),
/// covered by a slack of 4e-6 |delta|_1 (> 60 ulps); the radius is padded by
/// 0.1 % and sin(theta) <= 1 bounds the cross term; pairs within 1e-4 rad of
/// parallel (rayBeamIntersect's parallel case is 1e-5) are kept; NaN keeps.
inline bool linesFarApart(const CameraSegment& segment, const Beam& beam, float radius) {
  const Vec3f delta = segment.ray.o - beam.origin;
  const Vec3f n = cross(segment.ray.d, beam.direction);
  const float n2 = dot(n, n);
  const float along = dot(delta, n);  // d |n|, signed
  const float r = radius * 1.001f;
  const float slack = 4e-6f * (std::abs(delta.x) + std::abs(delta.y) + std::abs(delta.z));
  // (r |n| + slack)^2 <= r^2 n2 + slack (2 r + slack), as |n| <= 1.
  return n2 > 1e-8f && along * along > r * r * n2 + slack * (2.0f * r + slack);
}

/// Does `segment` pass within `radius` of `beam` (through its kernel region,
/// with an overlap of positive length)? On true, `hit` holds the estimate's
/// geometry; false leaves `hit` unspecified. Non-finite or degenerate input
/// (radius, length or tMax not > 0, NaN anywhere) gives false.
bool rayBeamIntersect(const CameraSegment& segment, const Beam& beam, float radius, RayBeamHit& hit,
                      RayBeamKernel kernel = RayBeamKernel::OneD);

}  // namespace femto::beams
