// Lanczos (windowed sinc) reconstruction filter, as in Mitsuba:
// sinc(pi x) sinc(pi x / lobes) for |x| < lobes pixels, zero beyond.
//
// | name  | type    | default | meaning                                   |
// |-------|---------|---------|-------------------------------------------|
// | lobes | integer | 3       | lobes of the sinc kept; also the radius   |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/math/constants.h>
#include <femto/render/rfilter.h>

namespace femto {

class LanczosFilter final : public ReconstructionFilter {
 public:
  explicit LanczosFilter(const Properties& props) : lobes_(int(props.getInt("lobes", 3))) {
    if (lobes_ < 1 || lobes_ > 16) props.raise("lobes", str("must be in [1, 16], got ", lobes_));
    setRadius(float(lobes_));
    buildTable();
  }

  float eval(float x) const override {
    x = std::abs(x);
    if (x >= radius()) return 0.0f;
    if (x < 1e-5f) return 1.0f;
    float a = Pi * x, b = a / float(lobes_);
    return (std::sin(a) / a) * (std::sin(b) / b);
  }

  std::string toString() const override { return str("LanczosFilter[lobes=", lobes_, "]"); }

 private:
  int lobes_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::LanczosFilter, ReconstructionFilter, "lanczos", "Lanczos windowed-sinc pixel filter")
