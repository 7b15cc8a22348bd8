// Catmull-Rom reconstruction filter: the Mitchell-Netravali cubic with
// B = 0, C = 1/2 (interpolating; Mitchell and Netravali 1988), as in Mitsuba.
//
// | name   | type  | default | meaning            |
// |--------|-------|---------|--------------------|
// | radius | float | 2       | support, in pixels |
#include <femto/core/plugin.h>
#include <femto/render/cubic_filter.h>

namespace femto {

class CatmullRomFilter final : public ReconstructionFilter {
 public:
  explicit CatmullRomFilter(const Properties& props) : cubic_(0.0f, 0.5f) { initRadiusAndTable(props, 2.0f); }

  float eval(float x) const override { return cubic_(2.0f * x / radius()); }

  std::string toString() const override { return str("CatmullRomFilter[radius=", radius(), "]"); }

 private:
  CubicFilter cubic_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::CatmullRomFilter, ReconstructionFilter, "catmullrom", "Catmull-Rom cubic pixel filter")
