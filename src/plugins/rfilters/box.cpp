// Box reconstruction filter: every sample counts fully for the pixels whose
// centres lie within `radius`; with the default radius each sample lands in
// exactly the pixel that contains it (no blur, but aliasing-prone).
//
// | name   | type  | default | meaning                      |
// |--------|-------|---------|------------------------------|
// | radius | float | 0.5     | half-width, in pixels (> 0)  |
#include <algorithm>
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/rfilter.h>

namespace femto {

class BoxFilter final : public ReconstructionFilter {
 public:
  explicit BoxFilter(const Properties& props) { initRadiusAndTable(props, 0.5f); }

  float eval(float x) const override { return std::abs(x) <= radius() ? 1.0f : 0.0f; }

  Profile profile() const override { return {Profile::Type::Box, radius()}; }

  std::string toString() const override { return str("BoxFilter[radius=", radius(), "]"); }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::BoxFilter, ReconstructionFilter, "box", "box pixel filter")
