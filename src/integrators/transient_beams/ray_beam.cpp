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

  // Causal OPL: PairOpl below.
  const PairOpl opl(segment, beam, r, hit);
  const double oplA = opl(tBegin), oplB = opl(tEnd);
  hit.oplBegin = std::min(oplA, oplB);
  hit.oplEnd = std::max(oplA, oplB);

  // Last line of defence: nothing non-finite reaches the film (NaN origins,
  // directions or indices propagate to here).
  return hit.kernel > 0.0f && std::isfinite(hit.kernel) && std::isfinite(hit.tRay) && std::isfinite(hit.tBeam) &&
         std::isfinite(hit.oplBegin) && std::isfinite(hit.oplEnd);
}


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
PairOpl::PairOpl(const CameraSegment& segment, const Beam& beam, float radius, const RayBeamHit& hit)
    : tBegin_(hit.tRayBegin), tEnd_(hit.tRayEnd), w_(segment.ray.d), offsetDelay_(beam.offsetDelay),
      delta_(segment.ray.o - beam.origin) {
  const float extension = beam.before * radius;
  fromStart_ = delta_ + beam.direction * extension;  // x(t) - (b - e v) = fromStart + t w
  shift_ = -double(beam.eta) * double(extension);
  etaBeam_ = beam.eta;
  etaCamera_ = segment.eta;
  s0_ = dot(delta_, beam.direction);
  cosTheta_ = dot(w_, beam.direction);
  const bool tilted = offsetDelay_.x != 0.0f || offsetDelay_.y != 0.0f || offsetDelay_.z != 0.0f;
  onExtension_ = tilted && s0_ + double(hit.tRay) * cosTheta_ < 0.0;
}

double PairOpl::operator()(float t) const {
  const double continuation = shift_ + etaBeam_ * startDistance(fromStart_, w_, t);
  if (!onExtension_) return etaCamera_ * t + continuation;
  const double s = s0_ + double(t) * cosTheta_;
  const double wave = etaBeam_ * s + double(dot(offsetDelay_, delta_)) + double(t) * double(dot(offsetDelay_, w_));
  return etaCamera_ * t + std::max(continuation, wave);
}

double PairOpl::slope(float t) const {
  const Vec3f x = fromStart_ + w_ * t;
  const double len = std::sqrt(double(dot(x, x)));
  const double continuation = len > 0.0 ? etaBeam_ * double(dot(x, w_)) / len : 0.0;
  if (!onExtension_) return etaCamera_ + continuation;
  const double s = s0_ + double(t) * cosTheta_;
  const double wave = etaBeam_ * s + double(dot(offsetDelay_, delta_)) + double(t) * double(dot(offsetDelay_, w_));
  const double cont = shift_ + etaBeam_ * len;
  return etaCamera_ + (cont >= wave ? continuation : etaBeam_ * cosTheta_ + double(dot(offsetDelay_, w_)));
}

int PairOpl::pieces(double tolerance, Piece* out, int maxPieces) const {
  // Split at the stationary point, if inside the overlap: with observer time
  // off (eta_c = 0) where the camera ray passes closest to the start; in
  // general g'(t) = eta_c + eta_b (ws + t) / |x(t)| = 0 at
  // t* = -ws - h eta_c / sqrt(eta_b^2 - eta_c^2) (h: the start's distance to the ray's line).
  float ends[3] = {tBegin_, tEnd_, tEnd_};
  int halves = 1;
  const double overlap = double(tEnd_) - double(tBegin_);
  if (!onExtension_) {
    const double ws = double(dot(fromStart_, w_));
    const Vec3f perp = fromStart_ - w_ * float(ws);
    const double h = std::sqrt(double(dot(perp, perp)));
    if (etaCamera_ < etaBeam_) {
      const double tStar = -ws - h * etaCamera_ / std::sqrt(etaBeam_ * etaBeam_ - etaCamera_ * etaCamera_);
      if (tStar > tBegin_ && tStar < tEnd_) ends[1] = float(tStar), halves = 2;
    }
    // |x(t) - start| bends at most 1 / h (its second derivative h^2 / |x - start|^3):
    // a chord over the overlap lies within eta_b L^2 / (8 h) of it.
    if (halves == 1 && etaBeam_ * overlap * overlap <= 8.0 * h * tolerance) return 1;
  }
  int n[2] = {1, 1}, total = 0;
  for (int k = 0; k < halves; ++k) {
    const double len = double(ends[k + 1]) - double(ends[k]);
    const double bend = std::abs(slope(ends[k + 1]) - slope(ends[k])) * len / 4.0;
    n[k] = tolerance > 0.0 && bend > tolerance ? int(std::min(std::ceil(bend / tolerance), 1e6)) : 1;
    total += n[k];
  }
  if (total > maxPieces) {  // share maxPieces between the halves by their need
    n[0] = halves == 2 ? std::clamp(int(double(maxPieces) * n[0] / total), 1, maxPieces - 1) : maxPieces;
    n[1] = maxPieces - n[0];
  }
  int m = 0;
  for (int k = 0; k < halves; ++k) {
    const double len = double(ends[k + 1]) - double(ends[k]);
    double ga = (*this)(ends[k]);
    for (int i = 0; i < n[k]; ++i, ++m) {
      const float b = i + 1 == n[k] ? ends[k + 1] : float(double(ends[k]) + len * (i + 1) / n[k]);
      const double gb = (*this)(b);
      out[m] = Piece{std::min(ga, gb), std::max(ga, gb), len / n[k] / overlap};
      ga = gb;
    }
  }
  return m;
}

}  // namespace femto::beams
