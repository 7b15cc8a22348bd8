// Low-discrepancy sampler (Mitsuba's `ldsampler`). The samples of a pixel
// are the first N points (N = sample_count rounded up to a power of two) of
// the base-2 (0,2)-sequence (van der Corput and Sobol's second dimension,
// Kollig and Keller 2002), Owen-scrambled independently per pixel and per
// dimension, so every 2D dimension is a (0, log2 N, 2)-net: one sample in each
// elementary interval of area 1/N (for N = 4^k, one in each cell of the
// sqrt(N) x sqrt(N) grid). Higher dimensions are "padded": each dimension
// visits the points in its own random order, as Mitsuba's ldsampler does, so
// the dimensions are not correlated. Values are a hash of (seed, pixel,
// dimension, sample): images are deterministic.
//
// | name         | type    | default | meaning                                                         |
// |--------------|---------|---------|-----------------------------------------------------------------|
// | sample_count | integer | 4       | samples per pixel, rounded up to a power of two (with a warning) |
// | dimension    | integer | 4       | Mitsuba 0.x: dimensions with low-discrepancy samples; femto pads all |
// | seed         | integer | 0       | Mitsuba 3: the sampler's seed, combined with --seed (render/sampler.h) |
//
// Mitsuba 0.6's `halton`, `hammersley` and `sobol` are this sampler under
// their names (src/plugins/CMakeLists.txt builds them from this file).
#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/transport/sample_sequences.h>

namespace femto {

class LowDiscrepancySampler : public DimensionalSampler {
 public:
  explicit LowDiscrepancySampler(const Properties& props) : DimensionalSampler(props) {
    int64_t dimension = props.getInt("dimension", 4, 1, Properties::Unbounded);
    if (sampleCount() > (1u << 30)) props.raise("sample_count", "must be at most 2^30");
    uint32_t n = 1;
    while (n < sampleCount()) n <<= 1;
    if (n != sampleCount()) {
      SourceLocation where = props.location("sample_count");
      logWarn(where.known() ? where.toString() + ": " : std::string(), "ldsampler: sample_count ", sampleCount(),
              " is not a power of two; using ", n);
    }
    setSampleCount(n);
  }

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<LowDiscrepancySampler>(*this); }

  float next1D() override {
    uint64_t key = nextDimensionKey();
    return sequence::toUnitFloat(sequence::owenScramble(sequence::vanDerCorput(pointIndex(key)), mixSeed(key, 1)));
  }

  Point2f next2D() override {
    uint64_t key = nextDimensionKey();
    uint32_t i = pointIndex(key);
    return {sequence::toUnitFloat(sequence::owenScramble(sequence::vanDerCorput(i), mixSeed(key, 1))),
            sequence::toUnitFloat(sequence::owenScramble(sequence::sobol2(i), mixSeed(key, 2)))};
  }

  std::string toString() const override { return str("LowDiscrepancySampler[sample_count=", sampleCount(), "]"); }

 private:
  /// The sequence point this sample uses in the dimension of `key`: a random
  /// permutation of the pixel's N points (beyond N, the sequence continues).
  uint32_t pointIndex(uint64_t key) const {
    uint32_t s = sampleIndex();
    return s < sampleCount() ? sequence::permuteIndex(s, sampleCount(), mixSeed(key, 0)) : s;
  }
};

}  // namespace femto

#if defined(FEMTO_LDSAMPLER_AS_QMC)
// Mitsuba 0.6's halton, hammersley and sobol samplers: quasi-Monte Carlo
// sequences, rendered with this scrambled (0,2)-sequence under their names
// (a different low-discrepancy point set of the same kind). `scramble` is accepted.
namespace femto {
class QuasiMonteCarloSampler final : public LowDiscrepancySampler {
 public:
  explicit QuasiMonteCarloSampler(const Properties& props) : LowDiscrepancySampler(props) {
    props.getInt("scramble", -1);
  }
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<QuasiMonteCarloSampler>(*this); }
};
}  // namespace femto
FEMTO_EXPORT_PLUGIN(femto::QuasiMonteCarloSampler, Sampler, FEMTO_SAMPLER_NAME,
                    "Mitsuba 0.6 sampler name, rendered as a scrambled (0,2)-sequence")
#else
FEMTO_EXPORT_PLUGIN(femto::LowDiscrepancySampler, Sampler, "ldsampler",
                    "Owen-scrambled (0,2)-sequence, padded across dimensions")
#endif
