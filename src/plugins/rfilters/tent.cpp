// Tent (triangle) reconstruction filter: weight falls linearly from 1 at the
// pixel centre to 0 at `radius` (bilinear reconstruction for radius 1).
//
// | name   | type  | default | meaning                      |
// |--------|-------|---------|------------------------------|
// | radius | float | 1.0     | half-width, in pixels (> 0)  |
#include <algorithm>
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/rfilter.h>

namespace femto {

class TentFilter final : public ReconstructionFilter {
 public:
  explicit TentFilter(const Properties& props) { initRadiusAndTable(props, 1.0f); }

  float eval(float x) const override { return std::max(0.0f, 1.0f - std::abs(x) / radius()); }

  Profile profile() const override { return {Profile::Type::Tent, radius()}; }

  std::string toString() const override { return str("TentFilter[radius=", radius(), "]"); }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::TentFilter, ReconstructionFilter, "tent", "tent (triangle) pixel filter")
