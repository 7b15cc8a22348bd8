#pragma once
// Spatially varying reflectances. Plugins that take a colour parameter accept
// either a value or a nested <texture> through textureOrColor().
#include <memory>
#include <string>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/render/interaction.h>

namespace femto {

class Texture : public Object {
 public:
  ObjectKind kind() const override { return ObjectKind::Texture; }
  virtual Color3f eval(const SurfaceInteraction& si) const = 0;
  /// Average value over the texture (for albedo estimates and sampling weights).
  virtual Color3f mean() const = 0;
  /// Size in texels of the image behind the texture, (0, 0) for procedural
  /// ones: a projector takes its aspect ratio from it, as Mitsuba does.
  virtual Point2i resolution() const { return Point2i(0, 0); }
};

/// A texture with one value everywhere (core-side; not a plugin).
class ConstantTexture final : public Texture {
 public:
  explicit ConstantTexture(const Color3f& value) : value_(value) {}
  Color3f eval(const SurfaceInteraction&) const override { return value_; }
  Color3f mean() const override { return value_; }
  std::string toString() const override;

 private:
  Color3f value_;
};

/// Where a 2D texture looks up a surface point: uv' = to_uv(uv). Reads
/// Mitsuba 3's `to_uv` transform or Mitsuba 0.6's `uscale`, `vscale`,
/// `uoffset`, `voffset` (uv' = uv * scale + offset; the loader's camelCase
/// upgrade leaves these names unchanged), not both.
class UvMapping {
 public:
  UvMapping() = default;
  explicit UvMapping(const Properties& props);
  Point2f operator()(const Point2f& uv) const;
  bool isIdentity() const { return toUv_.isIdentity(); }
  const Transform& transform() const { return toUv_; }

 private:
  Transform toUv_;
};

/// Parameter `name` as a texture: a nested/referenced <texture> object under
/// that name, or an <rgb>/<spectrum>/<float> value, or `def` when absent.
std::shared_ptr<Texture> textureOrColor(const Properties& props, const std::string& name, const Color3f& def);

}  // namespace femto
