// Gaussian reconstruction filter, Mitsuba's default. Truncated at 4 standard
// deviations and shifted down by its value there so that it reaches zero
// continuously at the radius (as Mitsuba 3's gaussian.cpp does), which avoids
// a visible step in the weights.
//
// | name   | type  | default | meaning                                         |
// |--------|-------|---------|-------------------------------------------------|
// | stddev | float | 0.5     | standard deviation, in pixels (> 0); radius = 4 stddev |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/rfilter.h>

namespace femto {

class GaussianFilter final : public ReconstructionFilter {
 public:
  explicit GaussianFilter(const Properties& props) {
    stddev_ = props.getFloat("stddev", 0.5f, Range::positive());
    setRadius(4.0f * stddev_);
    alpha_ = -1.0f / (2.0f * stddev_ * stddev_);
    bias_ = std::exp(alpha_ * radius() * radius());
    buildTable();
  }

  float eval(float x) const override { return std::max(0.0f, std::exp(alpha_ * x * x) - bias_); }

  Profile profile() const override { return {Profile::Type::Gaussian, stddev_}; }

  std::string toString() const override { return str("GaussianFilter[stddev=", stddev_, "]"); }

 private:
  float stddev_, alpha_ = 0.0f, bias_ = 0.0f;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::GaussianFilter, ReconstructionFilter, "gaussian", "truncated Gaussian pixel filter")
