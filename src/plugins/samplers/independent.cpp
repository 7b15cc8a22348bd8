// Independent sampler: uniform pseudo-random numbers from PCG32, no
// stratification. Each sample of each pixel has its own stream, seeded from
// mixSeed(mixSeed(seed, pixel index), sample index): a pixel's samples do not
// depend on the thread or tile order, and a sample's numbers do not depend on
// how many numbers the samples before it used. The latter makes a transient
// render split into time windows add up exactly to the whole window: a path
// stopped at one window's horizon would otherwise shift the next sample's
// random numbers (docs/transient-film.md, "Splitting a render").
//
// | name         | type    | default | meaning                 |
// |--------------|---------|---------|-------------------------|
// | sample_count | integer | 4       | samples per pixel (> 0) |
// | seed         | integer | 0       | Mitsuba 3: the sampler's seed, combined with --seed (render/sampler.h) |
#include <femto/core/plugin.h>
#include <femto/math/pcg32.h>
#include <femto/render/sampler.h>

namespace femto {

class IndependentSampler final : public Sampler {
 public:
  explicit IndependentSampler(const Properties& props) : Sampler(props) {}

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }
  void startPixel(uint64_t seed, uint64_t pixelIndex) override {
    markPixel(seed, pixelIndex);
    pixelSeed_ = mixSeed(seed, pixelIndex);
    sampleIndex_ = 0;
    rng_.seed(mixSeed(pixelSeed_, sampleIndex_));
  }
  void advance() override {
    markSample();
    rng_.seed(mixSeed(pixelSeed_, ++sampleIndex_));
  }
  float next1D() override { return rng_.nextFloat(); }
  Point2f next2D() override {
    float x = rng_.nextFloat();
    float y = rng_.nextFloat();
    return {x, y};
  }

  /// Samples per pixel may change between renders (no derived state).
  ParameterValues editableParameters() const override { return {{"sample_count", {double(sampleCount())}}}; }
  void setParameter(const std::string& name, const std::vector<double>& value) override {
    if (name != "sample_count") return Sampler::setParameter(name, value);
    setSampleCount(uint32_t(editableNumber(toString(), name, value, 1.0, 4294967295.0, true)));
  }

  std::string toString() const override { return str("IndependentSampler[sample_count=", sampleCount(), "]"); }

 private:
  PCG32 rng_;
  uint64_t pixelSeed_ = 0, sampleIndex_ = 0;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::IndependentSampler, Sampler, "independent", "uniform random samples (PCG32)")
