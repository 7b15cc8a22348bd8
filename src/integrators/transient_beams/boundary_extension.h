#pragma once
// Kernel extensions of beams past the boundaries where they end or start
// (docs/design/photon-beams.md, "Boundary extension"): the ray x beam estimate is
// the beam density blurred over a disc of radius r across each beam; within
// r of a boundary part of the disc lies behind it, where no beam runs, so
// the estimate loses, to first order in r, 2 r / (3 pi) of the density per
// end of a camera segment (radius_rule.h). A beam that ends on a boundary
// is continued straight past it, and a beam that leaves one straight before
// it, by r / |cos theta_n| (theta_n: its angle to the surface normal), i.e.
// to depth r behind the boundary, with the density the beam's attenuation
// gives there (extensionContinuation below; T_beam at the clamped beam
// parameter, ray_beam.cpp, times that continuation). Behind
// a planar boundary the extensions then hold exactly the beams the disc
// misses, up to the density's gradient: the loss becomes second order.
// Only camera segments of the beam's medium gather (camera_tracer.cpp), so
// the extension counts only where the disc of such a segment reaches past
// the boundary. Not extended: boundaries with the same medium on both sides
// (the disc sees real beams there), beams ended by Russian roulette or the
// horizon, beams from emitters (area lights on a boundary keep a first-order
// loss). The timing stays causal: a pair's OPL is measured from the beam's
// start (ray_beam.h), wherever along the extension it falls.
#include <algorithm>
#include <cmath>

#include <femto/math/spectrum.h>
#include <femto/math/vector.h>

namespace femto {
struct SurfaceInteraction;
class Medium;
}  // namespace femto

namespace femto::beams {

/// Longest extension, in kernel radii: grazing beams (|cos theta_n| below
/// 1 / MaxBoundaryExtension) reach less than r deep. Their share of the
/// first-order loss (a beam's disc reaches r sin theta_n past the boundary,
/// so the loss per direction goes as sin theta_n; isotropic beams) is
/// int_0^(1/M) sqrt(1 - mu^2) dmu / (pi / 4) <= 4 / (pi M): 8 % for M = 16.
constexpr float MaxBoundaryExtension = 16.0f;
/// The part of the first-order boundary loss the extension leaves (above).
constexpr double BoundaryLossLeft = 4.0 / (3.14159265358979323846 * MaxBoundaryExtension);

/// Extension in kernel radii of a beam along unit `d` through a boundary
/// of normal `n`: 1 / |cos theta_n|, at most MaxBoundaryExtension.
inline float boundaryExtension(const Normal3f& n, const Vec3f& d) {
  const float c = std::abs(dot(n, d)) / std::max(length(n), 1e-30f);
  return c * MaxBoundaryExtension > 1.0f ? 1.0f / c : MaxBoundaryExtension;
}

/// Beam::offsetDelay of a beam along unit `d` that entered its medium
/// through a pass-through boundary of normal `n`, where the index rose by
/// `etaStep` (eta - eta_before): etaStep q, q = n / (n.d) - d (q . (x - b)
/// is how much farther than s(x) the light reaching x has run in the
/// medium, for a plane wave through a planar boundary; docs/design/photon-beams.md,
/// "Timing the extension before a beam's start"). |q| = tan theta_n, capped
/// as the extension is (boundaryExtension: 1 / cos theta_n <= M). Zero
/// where the index does not change.
inline Vec3f boundaryOffsetDelay(const Normal3f& n, const Vec3f& d, float etaStep) {
  if (etaStep == 0.0f) return Vec3f(0.0f);
  const Vec3f& normal = n;
  const float nd = dot(normal, d), nn = dot(normal, normal);
  if (!(nn > 0.0f)) return Vec3f(0.0f);
  Vec3f q = normal * (1.0f / nd) - d;  // nd = 0 (tangent) gives inf: capped below
  const float maxTan = std::sqrt(MaxBoundaryExtension * MaxBoundaryExtension - 1.0f);
  const float tan2 = dot(q, q);
  if (!(tan2 <= maxTan * maxTan)) {
    // Tangent or beyond the cap: q's direction is the normal's part across d.
    const Vec3f across = normal - d * nd;
    const float a = length(across);
    q = a > 0.0f ? across * (std::copysign(maxTan, nd) / a) : Vec3f(0.0f);
  }
  return q * etaStep;
}

/// The density an extension carries, relative to the beam's at the end it
/// extends: the beam's own attenuation continued past that end, exp(-sigma_t
/// beyond) with `beyond` = s - clamp(s, 0, length) (negative before the
/// start: the density rises back toward the boundary's far side, as the
/// field the disc misses would). A symmetric kernel then cancels the
/// density's gradient to first order, as it does inside the medium; held at
/// the end's value it leaves a loss of order sigma_t r times the share of
/// the disc behind the boundary where light concentrates at a lit boundary.
/// Random media seed 21 (sigma_t 1.72, r = 0.06, 6 seeds, against r =
/// 0.004): -1.11 % held, -0.82 % with the start's continuation alone,
/// -1.01 % with both ends' (past the exits the density falls). Homogeneous
/// media only (1 elsewhere: sigma_t beyond the boundary is not known there).
Color3f extensionContinuation(const Medium& medium, float beyond);

/// Is the medium on the far side of `si`, seen along `across`, the same as
/// `medium`? Shapes that declare media say so; a shape without media is
/// transparent to them when it is a pass-through (index-matched) boundary
/// and a solid (nothing behind its surface) otherwise.
bool sameMediumAcross(const SurfaceInteraction& si, const Vec3f& across, const Medium* medium);

}  // namespace femto::beams
