#pragma once
// Russian roulette along a photon beam: long beams become short where their
// light has mostly been absorbed or scattered away, without changing any
// estimate's expectation.
//
// A long beam (Jarosz et al. 2011, sec. 5.2) reaches from its origin to the
// next surface, and every estimate weights it by its transmittance T(s) at the
// beam parameter s where the camera ray meets it. In a large or optically thick
// medium that beam is many mean free paths long while T(s) is negligible over
// most of it: it costs (bounding boxes, map queries, pair tests) in proportion
// to its length but contributes almost nothing. So the photon tracer ends it at
// a random length
//
//   lambda = s0 + E / sigma,   E ~ Exp(1), independent of everything else,
//   s0 = ln(1 / Tau) / sigma   (where exp(-sigma s) falls to Tau),
//
// i.e. the beam survives to s with probability S(s) = P(lambda > s) =
// min(1, exp(-sigma s) / Tau), and estimates weight it by T(s) / S(s) instead
// of T(s).
//
// Unbiasedness: for any s, E_lambda[ 1{s < lambda} T(s) / S(s) ] =
// S(s) T(s) / S(s) = T(s), the long beam's weight. The identity holds for every
// point of the beam separately, so any estimate that integrates the beam
// against a kernel (ray x beam 1D, the exact blurred cylinder) keeps its
// expectation: the truncated end is a beam end like one at a surface, and the
// kernel clips the pair there. (The estimate evaluates T / S at one point of
// the kernel's chord, as it already does T: the same O(r) kernel blur, which
// vanishes with the radius.)
//
// Variance: S is 1 until T = Tau (in a grey medium with sigma = sigma_t), and
// past s0 the weight is the constant Tau (grey) or falls (sigma_t > sigma in
// other channels): the weights never exceed Tau beyond s0, so the roulette
// adds little variance where it removes most of a beam's length. The mean
// truncated length is (ln(1 / Tau) + 1) / sigma: 2.4 mean free paths for
// Tau = 1/4, against up to the medium's extent (or 40 mean free paths,
// medium_extent.h) for long beams. Tau = 1 would be Jarosz et al.'s short
// beams (weight 1 in a grey medium); Tau -> 0 the long beams.
//
// sigma is the smallest channel of a homogeneous medium's extinction (the
// channel that survives longest sets the length). Heterogeneous media keep
// long beams: their T(s) / S(s) could exceed Tau where the density falls
// below any rate fixed per medium.
//
// Along a camera segment (camera_tracer.cpp, gatherBeams) the same rule ends
// the gather, from GatherTau: the segment's query stops at a lambda drawn as
// above from its start, and every pair found weighs T_cam(t) / S(t) at its
// camera parameter t instead of T_cam(t). The proof is the one above with the
// camera parameter for s: each point of the segment keeps its expectation. A
// pair's kernel clipped at lambda is the blurred beam cut there, and past s0
// the weight T_cam / S is the constant GatherTau (grey), so the clipped
// chord's expectation over lambda is the chord's integral of T_cam exactly.
// Only the gather is cut: the camera path itself still reaches the surface
// behind, attenuated by T_cam. In an optically thick medium a camera segment
// many mean free paths long then pays for the beams within about
// ln(1 / GatherTau) + 1 = 4 mean free paths of where it enters instead of
// every beam along it (the media suite's thick medium: 3.8x fewer candidates).
// Why 5 % and not the beams' 25 %: time bins. A bin whose light comes only
// from past s0 along the camera rays (single scattering far down a segment:
// its OPL grows with t) has its variance multiplied by up to 1 / S(t) =
// e^{sigma (t - s0)}, which no other sample of the pixel offsets. At 25 % the
// media suite's large medium (single scattering, camera inside) lost 1.5x in
// relMSE and a single-ray closed-form test saw late bins no pass reached; at
// 5 % (s0 = 3 mean free paths) both are as without it, and the thick
// medium's earliest 1 % of light, which only the deepest points see, keeps
// its error (docs/design/photon-beams.md, "Russian roulette along camera segments").
#include <cmath>

#include <femto/math/constants.h>

namespace femto {
class Medium;
}

namespace femto::beams {

class BeamRoulette {
 public:
  /// The transmittance at which the roulette of beams starts (see above).
  static constexpr float Tau = 0.25f;
  /// The transmittance at which the roulette of a camera segment's gather
  /// starts (see above, "Along a camera segment").
  static constexpr float GatherTau = 0.05f;

  /// The roulette of beams crossing `medium`: none (never truncates) for a
  /// heterogeneous medium or one that does not attenuate.
  static BeamRoulette of(const Medium& medium, float tau = Tau);
  /// A roulette with decay rate `sigma` (> 0 and finite, else none) that
  /// starts where exp(-sigma s) falls to `tau` (in (0, 1]; Tau for beams,
  /// GatherTau for camera segments).
  explicit BeamRoulette(float sigma = 0.0f, float tau = Tau);

  bool active() const { return sigma_ > 0.0f; }
  /// s0, where S starts to fall below 1; Infinity when inactive.
  float start() const { return start_; }
  /// A random beam length lambda from `u` in [0, 1); Infinity when inactive.
  float sampleLength(float u) const;
  /// S(s): the probability that a beam survives to parameter s.
  float survival(float s) const;
  /// 1 / S(s), the weight the camera side multiplies a beam's estimate by.
  float inverseSurvival(float s) const;

 private:
  float sigma_ = 0.0f;
  float start_ = Infinity;  // s0
};

}  // namespace femto::beams
