// Ray x beam 1D-kernel estimate, transient (see ray_beam.h and
// docs/design/photon-beams.md for the derivation of every step).
#include <transient_beams/ray_beam.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>

namespace femto::beams {

namespace {

// |cos(theta)| below this: the camera segment runs perpendicular to the beam,
// its projection s(t) is constant and the cap planes do not clip it (dividing
// by cos(theta) would produce inf or 0/0).
constexpr float Perpendicular = 1e-12f;
// sin^2(theta) below this (theta < 1e-5 rad, about the rounding of unit float
// vectors): the lines are parallel and the closest-approach quadratic
// degenerates (its leading coefficient is rounding noise). The distance to
// the axis then varies by < 1e-5 per unit length; it is taken at the middle
// of the slab-clipped segment.
constexpr float ParallelSin2 = 1e-10f;

/// Distance from ray.o + t w to the beam's start, |delta + t w| (delta = ray.o - b), in double.
double startDistance(const Vec3f& delta, const Vec3f& w, float t) {
  const double x = double(delta.x) + double(t) * w.x, y = double(delta.y) + double(t) * w.y,
               z = double(delta.z) + double(t) * w.z;
  return std::sqrt(x * x + y * y + z * z);
}

}  // namespace

bool rayBeamIntersect(const CameraSegment& segment, const Beam& beam, float radius, RayBeamHit& hit,
                      RayBeamKernel kernel) {
  const float r = radius, r2 = radius * radius, length = beam.length, tMax = segment.tMax;
  // Degenerate input: no kernel region or no segment (NaN fails every test).
  if (!(r2 > 0.0f) || !(r < Infinity) || !(length > 0.0f) || !(length < Infinity) || !(tMax > 0.0f)) return false;

  const Vec3f& w = segment.ray.d;
  const Vec3f& v = beam.direction;
  const Vec3f delta = segment.ray.o - beam.origin;
  const float cosTheta = dot(w, v);
  const float s0 = dot(delta, v);  // projection of ray.o on the beam: s(t) = s0 + t cos(theta)

  // Components perpendicular to the beam: the distance to its axis is
  // |dPerp + t wPerp|, and |.|^2 < r^2 is the quadratic a t^2 + 2 b t + e < 0.
  const Vec3f wPerp = w - v * cosTheta;
  const Vec3f dPerp = delta - v * s0;
  const float a = dot(wPerp, wPerp);  // sin^2(theta)
  const bool parallel = !(a > ParallelSin2);
  // Discriminant / 4 = b^2 - a e = a r^2 - |dPerp x wPerp|^2 (Lagrange's
  // identity): no cancellation of the large terms b^2 and a |dPerp|^2.
  // |dPerp x wPerp|^2 / a = d^2, the squared distance between the lines.
  // Tested first: it rejects most candidates a beam map returns, division-free
  // (with BeamMap::Cull::Lines the map has already dropped most of those:
  // linesFarApart, ray_beam.h, keeps every pair this test keeps).
  const Vec3f m = cross(dPerp, wPerp);
  const float disc = a * r2 - dot(m, m);
  if (!parallel && !(disc > 0.0f)) return false;  // passes at d >= r (tangent: zero-length chord)

  // Slab between the cap planes, sBegin <= s(t) <= sEnd, intersected with
  // [0, tMax]: the beam [0, length] plus its extensions past boundaries
  // (boundary_extension.h).
  const float sBegin = -beam.before * r, sEnd = length + beam.after * r;
  float lo = 0.0f, hi = tMax;
  if (std::abs(cosTheta) > Perpendicular) {
    const float invCos = 1.0f / cosTheta;
    const float t0 = (sBegin - s0) * invCos, t1 = (sEnd - s0) * invCos;
    lo = std::max(lo, std::min(t0, t1));
    hi = std::min(hi, std::max(t0, t1));
  } else if (!(s0 >= sBegin && s0 <= sEnd)) {
    return false;
  }
  if (!(hi > lo)) return false;

  float tBegin, tEnd, tRay;
  bool oneD = false;
  float invSinTheta = 0.0f;
  if (!parallel) {
    const float invA = 1.0f / a;
    invSinTheta = 1.0f / std::sqrt(a);
    const float tClosest = -dot(dPerp, wPerp) * invA;
    const float halfChord = std::sqrt(disc) * invA;  // sqrt(r^2 - d^2) / sin(theta)
    tBegin = std::max(lo, tClosest - halfChord);
    tEnd = std::min(hi, tClosest + halfChord);
    // The 1D kernel's average over the lateral offset equals the chord's only
    // if the longest chord (d = 0, half-length r / sin(theta)) is unclipped.
    // tClosest, the slab and tMax do not change with the offset, so every
    // offset of this pair makes the same choice: the mix is unbiased.
    const float maxHalfChord = r * invSinTheta;
    oneD = kernel == RayBeamKernel::OneD && tClosest - maxHalfChord >= lo && tClosest + maxHalfChord <= hi;
    tRay = oneD ? tClosest : 0.5f * (tBegin + tEnd);
  } else {
    const Vec3f mid = dPerp + wPerp * (0.5f * (lo + hi));
    if (!(dot(mid, mid) < r2)) return false;
    tBegin = lo, tEnd = hi;
    tRay = 0.5f * (tBegin + tEnd);
  }
  if (!(tEnd > tBegin)) return false;  // zero-length overlap (touches a cap edge or tMax)

  hit.tRayBegin = tBegin;
  hit.tRayEnd = tEnd;
  hit.tRay = tRay;
  hit.oneD = oneD;
  hit.tBeam = std::clamp(s0 + tRay * cosTheta, 0.0f, length);
  hit.kernel = oneD ? 0.5f * invSinTheta / r : (tEnd - tBegin) * InvPi / r2;

  // Causal OPL (docs/design/photon-beams.md, "Causality"): light at camera point
  // x(t) came from the beam's start b, which it left at beam.opl, and
  // travelled at least |x(t) - b| in the medium (eta_b): g(t) = eta_c t +
  // eta_b |x(t) - b|. Away from the start |x(t) - b| = s(t) + gap^2 / (2 s):
  // the projection's OPL eta_c t + eta_b s(t) up to second order; near the
  // start (the kernel straddling the light cone) it keeps every estimate
  // after the light could arrive. g is convex in t, so the straight line
  // between its values at the overlap's ends lies above it: the deposit,
  // uniform over [g(tBegin), g(tEnd)], is that line, never earlier than g,
  // and by the triangle inequality never before the earliest path
  // b -> x(t) -> ray.o.
  // A beam extended before its start (boundary_extension.h: it entered its
  // medium or left a surface at b) is timed from the extension's start
  // b - e v, e = before r, at the OPL its light would have there, beam.opl -
  // eta_b e: for points on the extension (s < 0) that is the continuation
  // beam.opl + eta_b s, the time of the real beams the extension stands for
  // (across a planar boundary the tangential gradient of the arrival time is
  // continuous, Snell's phase matching, so the neighbours that enter or
  // leave the boundary near x arrive there at beam.opl + eta_b s(x));
  // measured from b instead (|x - b| = |s| + ...) it was 2 eta_b |s| late,
  // up to 32 eta_b r for grazing beams: issue 14's random media seed 2 put
  // energy 5+ bins after the latest arrival at r = 0.083
  // (docs/design/photon-beams.md, "Timing the extension before a beam's start").
  // A beam that entered through a pass-through boundary where the index
  // changed (light changes speed, not direction: the random media family)
  // has a tilted wavefront: light at x crossed the boundary at another
  // point and ran lambda(x) = s(x) + q.(x - b) in the medium, arriving at
  // P(x) = beam.opl + eta_b s(x) + offsetDelay.(x - b) (a plane wave through
  // a planar boundary, boundary_extension.h). On the extension (the pair's
  // point before the start) the estimate stands for exactly that light, and
  // the continuation at eta_b is earlier by (eta_b - eta_before)(|s| +
  // q.(x - b)) > 0: random media seed 21 put energy a bin before the
  // earliest arrival. The later of the two is taken: P is linear in t and
  // the continuation convex, so their maximum is convex and the chord
  // argument holds; P leaves out the lateral path, and alone it was early
  // by eta_b u^2 / 2R for a beam entering a sphere of radius R head-on
  // (camera points at offset u lie before its start there: seed 23 with
  // r / 4 put energy into the bin before the arrival). On the
  // beam itself the estimate keeps its own light's time above (the tilt
  // moves neighbours either way by offsetDelay.(x - b), a blur without a
  // mean shift). offsetDelay is zero for every other beam.
  const float extension = beam.before * r;
  const Vec3f fromStart = delta + v * extension;  // x(t) - (b - e v) = fromStart + t w
  const double shift = -double(beam.eta) * double(extension);
  const bool tilted = beam.offsetDelay.x != 0.0f || beam.offsetDelay.y != 0.0f || beam.offsetDelay.z != 0.0f;
  const bool onExtension = tilted && double(s0) + double(tRay) * double(cosTheta) < 0.0;
  auto opl = [&](float t) {
    const double continuation = shift + double(beam.eta) * startDistance(fromStart, w, t);
    if (!onExtension) return double(segment.eta) * t + continuation;
    const double s = double(s0) + double(t) * double(cosTheta);
    const double wave =
        double(beam.eta) * s + double(dot(beam.offsetDelay, delta)) + double(t) * double(dot(beam.offsetDelay, w));
    return double(segment.eta) * t + std::max(continuation, wave);
  };
  const double oplA = opl(tBegin), oplB = opl(tEnd);
  hit.oplBegin = std::min(oplA, oplB);
  hit.oplEnd = std::max(oplA, oplB);

  // Last line of defence: nothing non-finite reaches the film (NaN origins,
  // directions or indices propagate to here).
  return hit.kernel > 0.0f && std::isfinite(hit.kernel) && std::isfinite(hit.tRay) && std::isfinite(hit.tBeam) &&
         std::isfinite(hit.oplBegin) && std::isfinite(hit.oplEnd);
}

}  // namespace femto::beams
