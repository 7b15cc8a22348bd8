// Stratified sampler (Mitsuba's `stratified`). The sample count is rounded
// up to a square m^2. In every dimension the samples of a pixel fall one per
// stratum: 1D dimensions split [0, 1) into m^2 intervals, 2D dimensions into
// an m x m grid. Each dimension assigns strata to sample indices through its
// own random permutation ("padding", Shirley 1991 / PBRT sec. 7.3), so the
// dimensions are not correlated. Every value is a hash of (seed, pixel,
// dimension, sample), so images are deterministic.
//
// | name         | type    | default | meaning                                                    |
// |--------------|---------|---------|------------------------------------------------------------|
// | sample_count | integer | 4       | samples per pixel, rounded up to a square (with a warning) |
// | jitter       | boolean | true    | random position inside each stratum (false: its centre)    |
// | dimension    | integer | 4       | Mitsuba 0.x: dimensions stratified; femto stratifies all    |
// | seed         | integer | 0       | Mitsuba 3: the sampler's seed, combined with --seed (render/sampler.h) |
//
// Mitsuba 3's `multijitter` and `orthogonal` are this sampler under their
// names (src/plugins/CMakeLists.txt builds them from this file).
#include <cmath>

#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/transport/sample_sequences.h>

namespace femto {

class StratifiedSampler : public DimensionalSampler {
 public:
  explicit StratifiedSampler(const Properties& props) : DimensionalSampler(props) {
    jitter_ = props.getBool("jitter", true);
    int64_t dimension = props.getInt("dimension", 4, 1, Properties::Unbounded);
    uint32_t m = 1;
    while (uint64_t(m) * m < sampleCount()) ++m;
    if (uint64_t(m) * m != sampleCount()) {
      SourceLocation where = props.location("sample_count");
      logWarn(where.known() ? where.toString() + ": " : std::string(), "stratified: sample_count ", sampleCount(),
              " is not a square; using ", m * m);
    }
    resolution_ = m;
    setSampleCount(m * m);
  }

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<StratifiedSampler>(*this); }

  float next1D() override {
    uint64_t key = nextDimensionKey();
    if (sampleIndex() >= sampleCount()) return sequence::toUnitFloat(randomBits(key, 0));
    uint32_t stratum = sequence::permuteIndex(sampleIndex(), sampleCount(), key);
    return (float(stratum) + offset(key, 0)) / float(sampleCount());
  }

  Point2f next2D() override {
    uint64_t key = nextDimensionKey();
    if (sampleIndex() >= sampleCount())
      return {sequence::toUnitFloat(randomBits(key, 0)), sequence::toUnitFloat(randomBits(key, 1))};
    uint32_t cell = sequence::permuteIndex(sampleIndex(), sampleCount(), key);
    float m = float(resolution_);
    return {(float(cell % resolution_) + offset(key, 0)) / m, (float(cell / resolution_) + offset(key, 1)) / m};
  }

  std::string toString() const override {
    return str("StratifiedSampler[sample_count=", sampleCount(), ", jitter=", jitter_ ? "true" : "false", "]");
  }

 private:
  /// Position inside the stratum, kept strictly below 1 so rounding never
  /// moves a sample into the next stratum.
  float offset(uint64_t key, uint32_t stream) const {
    return jitter_ ? std::min(sequence::toUnitFloat(randomBits(key, stream)), 0.99999f) : 0.5f;
  }

  uint32_t resolution_ = 1;
  bool jitter_ = true;
};

}  // namespace femto

#if defined(FEMTO_STRATIFIED_AS_MULTIJITTER)
// Mitsuba 3's multi-jittered and orthogonal-array samplers: stratified
// samples under their names (the same one-per-stratum property in every 2D
// dimension; the extra cross-stratification of those designs is not
// reproduced). orthogonal's `strength` is accepted.
namespace femto {
class MultiJitterSampler final : public StratifiedSampler {
 public:
  explicit MultiJitterSampler(const Properties& props) : StratifiedSampler(props) {
    props.getInt("strength", 2);
  }
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<MultiJitterSampler>(*this); }
};
}  // namespace femto
FEMTO_EXPORT_PLUGIN(femto::MultiJitterSampler, Sampler, FEMTO_SAMPLER_NAME,
                    "Mitsuba 3 sampler name, rendered as stratified samples")
#else
FEMTO_EXPORT_PLUGIN(femto::StratifiedSampler, Sampler, "stratified", "stratified (jittered) samples, one per stratum")
#endif
