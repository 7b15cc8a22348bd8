#include <femto/render/sampler.h>

#include <algorithm>

namespace femto {

Sampler::Sampler(const Properties& props) {
  sampleCount_ = uint32_t(props.getInt("sample_count", 4, 1, int64_t(UINT32_MAX)));
  // Mitsuba 3's per-scene seed of the sampler (mi.render's seed argument
  // plays the role of femto's --seed; the two are combined).
  sceneSeed_ = uint64_t(props.getInt("seed", 0, 0, Properties::Unbounded));
}

namespace {
// splitmix64 finaliser (Steele et al. 2014, "Fast splittable pseudorandom number generators").
uint64_t splitmix(uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
}  // namespace

uint64_t mixSeed(uint64_t a, uint64_t b) { return splitmix(splitmix(a) ^ b); }

float Sampler::stratum(uint64_t salt) const {
  const double shift = double(mixSeed(stratumKey_, salt) >> 11) * 0x1p-53;
  const double v = shift + double(stratumIndex_ % sampleCount_) / double(sampleCount_);
  // Below 1 in float too (v < 1 in double may round up to 1.0f).
  return std::min(float(v < 1.0 ? v : v - 1.0), 0x1.fffffep-1f);
}

uint64_t Sampler::cameraSeed(uint64_t renderSeed) const {
  return sceneSeed_ == 0 ? renderSeed : mixSeed(renderSeed, sceneSeed_);
}

}  // namespace femto
