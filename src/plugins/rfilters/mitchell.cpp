// Mitchell-Netravali reconstruction filter (Mitchell and Netravali,
// "Reconstruction Filters in Computer Graphics", SIGGRAPH 1988, eq. 8), as in
// Mitsuba: the cubic with parameters B and C over |x| < 2 in units of
// radius / 2. B = C = 1/3 is the authors' recommendation; negative lobes
// sharpen edges (the film normalises by the summed weights).
//
// | name   | type  | default | meaning                                  |
// |--------|-------|---------|------------------------------------------|
// | B      | float | 1/3     | blur parameter                           |
// | C      | float | 1/3     | ringing parameter                        |
// | radius | float | 2       | support, in pixels                       |
#include <femto/core/plugin.h>
#include <femto/render/cubic_filter.h>

namespace femto {

class MitchellFilter final : public ReconstructionFilter {
 public:
  explicit MitchellFilter(const Properties& props)
      : cubic_(props.getFloat("B", 1.0f / 3.0f), props.getFloat("C", 1.0f / 3.0f)) {
    initRadiusAndTable(props, 2.0f);
  }

  float eval(float x) const override { return cubic_(2.0f * x / radius()); }

  std::string toString() const override {
    return str("MitchellFilter[B=", cubic_.b(), ", C=", cubic_.c(), ", radius=", radius(), "]");
  }

 private:
  CubicFilter cubic_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::MitchellFilter, ReconstructionFilter, "mitchell", "Mitchell-Netravali cubic pixel filter")
