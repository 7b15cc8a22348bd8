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
#include <cctype>
#include <string>

#include <femto/core/plugin.h>
#include <femto/render/cubic_filter.h>

namespace femto {

class MitchellFilter final : public ReconstructionFilter {
 public:
  explicit MitchellFilter(const Properties& props) : cubic_(parameter(props, "B"), parameter(props, "C")) {
    initRadiusAndTable(props, 2.0f);
  }

  float eval(float x) const override { return cubic_(2.0f * x / radius()); }

  /// "B" or "C" as Mitsuba names them; Mitsuba 0.6 files reach here as "b"
  /// and "c" (the loader lower-cases 0.6 names).
  static float parameter(const Properties& props, const std::string& upper) {
    std::string lower(1, char(std::tolower(static_cast<unsigned char>(upper[0]))));
    if (props.has(lower)) {
      if (props.has(upper)) props.raise(lower, str("\"", lower, "\" and \"", upper, "\" are one parameter: give one of them"));
      return props.getFloat(lower);
    }
    return props.getFloat(upper, 1.0f / 3.0f);
  }

  std::string toString() const override {
    return str("MitchellFilter[B=", cubic_.b(), ", C=", cubic_.c(), ", radius=", radius(), "]");
  }

 private:
  CubicFilter cubic_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::MitchellFilter, ReconstructionFilter, "mitchell", "Mitchell-Netravali cubic pixel filter")
