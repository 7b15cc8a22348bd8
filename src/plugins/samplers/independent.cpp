// Independent sampler: uniform pseudo-random numbers from PCG32, no
// stratification. Each pixel's stream is seeded from mixSeed(seed, pixel
// index), so a pixel's samples do not depend on the thread or tile order.
//
// | name         | type    | default | meaning                 |
// |--------------|---------|---------|-------------------------|
// | sample_count | integer | 4       | samples per pixel (> 0) |
#include <femto/core/plugin.h>
#include <femto/math/pcg32.h>
#include <femto/render/sampler.h>

namespace femto {

class IndependentSampler final : public Sampler {
 public:
  explicit IndependentSampler(const Properties& props) : Sampler(props) {}

  std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }
  void startPixel(uint64_t seed, uint64_t pixelIndex) override { rng_.seed(mixSeed(seed, pixelIndex)); }
  void advance() override {}  // one continuous stream per pixel
  float next1D() override { return rng_.nextFloat(); }
  Point2f next2D() override {
    float x = rng_.nextFloat();
    float y = rng_.nextFloat();
    return {x, y};
  }

  std::string toString() const override { return str("IndependentSampler[sample_count=", sampleCount(), "]"); }

 private:
  PCG32 rng_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::IndependentSampler, Sampler, "independent", "uniform random samples (PCG32)")
