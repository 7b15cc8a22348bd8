// Russian roulette along photon beams (see beam_roulette.h for the rule and
// the proof that it keeps every estimate's expectation).
#include <transient_beams/beam_roulette.h>

#include <algorithm>

#include <femto/render/medium.h>

namespace femto::beams {
namespace {
/// The largest float below 1: u is clamped to it so that the length stays finite.
constexpr float MaxUniform = 0x1.fffffep-1f;
}  // namespace

BeamRoulette BeamRoulette::of(const Medium& medium, float tau) {
  if (!medium.isHomogeneous()) return BeamRoulette();
  const Color3f sigmaT = medium.majorant();  // a homogeneous medium's extinction
  return BeamRoulette(std::min(sigmaT.r, std::min(sigmaT.g, sigmaT.b)), tau);
}

BeamRoulette::BeamRoulette(float sigma, float tau) {
  if (!(sigma > 0.0f) || !std::isfinite(sigma) || !(tau > 0.0f && tau <= 1.0f)) return;
  sigma_ = sigma;
  start_ = std::log(1.0f / tau) / sigma;
}

float BeamRoulette::sampleLength(float u) const {
  if (!active()) return Infinity;
  // -log1p(-u) is Exp(1) for u in [0, 1), finite since u < 1.
  return start_ - std::log1p(-std::min(u, MaxUniform)) / sigma_;
}

float BeamRoulette::survival(float s) const {
  if (!active() || !(s > start_)) return 1.0f;
  return std::exp(-sigma_ * (s - start_));
}

float BeamRoulette::inverseSurvival(float s) const {
  if (!active() || !(s > start_)) return 1.0f;
  // Only evaluated for s < lambda, where sigma (s - s0) < E: finite unless E
  // itself was huge, which u < 1 bounds (E <= 24 in float).
  return std::exp(sigma_ * (s - start_));
}

}  // namespace femto::beams
