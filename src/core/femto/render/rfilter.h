#pragma once
// Pixel reconstruction filters. The film splats each sample with weights from
// a table of the filter over [0, radius] (Mitsuba-style), which makes the cost
// independent of the filter's closed form.
#include <array>

#include <femto/core/object.h>
#include <femto/core/properties.h>

namespace femto {

class ReconstructionFilter : public Object {
 public:
  ObjectKind kind() const override { return ObjectKind::ReconstructionFilter; }
  /// Filter radius in pixels; samples farther than this from a pixel centre do not touch it.
  float radius() const { return radius_; }
  /// Separable 1D profile, defined for |x| <= radius().
  virtual float eval(float x) const = 0;
  /// Tabulated eval(); call once from the subclass constructor after setting the radius.
  float evalTabulated(float x) const;

  /// The filter's shape in words, for films that reuse a pixel filter along
  /// their time axis (Mitsuba 2's streak film takes <rfilter name="tfilter">).
  struct Profile {
    enum class Type { Box, Tent, Gaussian, Other };
    Type type = Type::Other;
    float width = 0.0f;  // box and tent: radius; gaussian: standard deviation
  };
  virtual Profile profile() const { return {}; }

 protected:
  void setRadius(float r);
  void buildTable();
  /// Read a positive "radius" parameter (default `def`) with file:line errors,
  /// set it and build the table: the whole constructor of simple filters.
  void initRadiusAndTable(const Properties& props, float def);

 private:
  static constexpr int TableSize = 64;
  float radius_ = 0.5f;
  float scale_ = 0.0f;
  std::array<float, TableSize + 1> table_{};
};

}  // namespace femto
