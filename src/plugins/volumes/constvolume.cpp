// constvolume: the same value everywhere (Mitsuba's "constvolume"), e.g. a
// constant albedo of a heterogeneous medium.
//
// | name  | type      | default | meaning            | unit |
// |-------|-----------|---------|--------------------|------|
// | value | float/rgb | 1       | the constant value | -    |
#include <femto/core/plugin.h>
#include <femto/render/volume.h>

namespace femto {

class ConstVolume final : public Volume {
 public:
  explicit ConstVolume(const Properties& props) : value_(props.getColor("value", Color3f(1.0f))) {
    if (!value_.isFinite()) props.raise("value", "must be finite");
  }

  float evalFloat(const Point3f&) const override { return value_.average(); }
  Color3f evalColor(const Point3f&) const override { return value_; }
  float maxFloat() const override { return value_.average(); }
  BoundingBox3f bbox() const override { return BoundingBox3f(); }

  std::string toString() const override { return str("ConstVolume[value=", value_, "]"); }

 private:
  Color3f value_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ConstVolume, Volume, "constvolume", "Constant volume")
