#pragma once
// Volumes: scalar or colour fields over space (<volume> in the XML), used by
// heterogeneous media for density and albedo. Lookups are in world space.
#include <femto/core/object.h>
#include <femto/math/bbox.h>
#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto {

class Volume : public Object {
 public:
  ObjectKind kind() const override { return ObjectKind::Volume; }

  /// Scalar value at world point `p` (a colour volume gives its average).
  virtual float evalFloat(const Point3f& p) const = 0;
  /// Colour value at `p` (a scalar volume gives grey).
  virtual Color3f evalColor(const Point3f& p) const = 0;
  /// Upper bound of evalFloat over all space (the majorant of delta tracking).
  virtual float maxFloat() const = 0;
  /// World-space box outside which the volume is zero; an invalid (empty)
  /// box means the volume is not bounded (e.g. a constant).
  virtual BoundingBox3f bbox() const = 0;
};

}  // namespace femto
