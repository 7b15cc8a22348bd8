// checkerboard: two colours alternating in squares of half a unit in uv
// (Mitsuba's pattern): color0 where the fractional parts of u and v are both
// below 1/2 or both above, color1 elsewhere. With the default mapping a
// shape whose uv span [0, 1]^2 shows 2 x 2 squares.
//
// | name                    | type              | default  | meaning                                       | unit |
// |-------------------------|-------------------|----------|-----------------------------------------------|------|
// | color0                  | rgb or texture    | 0.4      | colour of the squares at uv in [0, 1/2)^2     | -    |
// | color1                  | rgb or texture    | 0.2      | colour of the other squares                   | -    |
// | to_uv                   | transform         | identity | maps surface uv to pattern uv                 | -    |
// | uscale, vscale          | float             | 1        | Mitsuba 0.6 alternative to to_uv: uv * scale  | -    |
// | uoffset, voffset        | float             | 0        | ... + offset                                  | -    |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/texture.h>

namespace femto {

class CheckerboardTexture final : public Texture {
 public:
  explicit CheckerboardTexture(const Properties& props)
      : color0_(textureOrColor(props, "color0", Color3f(0.4f))),
        color1_(textureOrColor(props, "color1", Color3f(0.2f))),
        toUv_(props) {}

  Color3f eval(const SurfaceInteraction& si) const override {
    Point2f uv = toUv_(si.uv);
    bool upperU = uv.x - std::floor(uv.x) > 0.5f, upperV = uv.y - std::floor(uv.y) > 0.5f;
    return upperU == upperV ? color0_->eval(si) : color1_->eval(si);
  }

  /// Each colour covers half of every unit square of pattern space.
  Color3f mean() const override { return (color0_->mean() + color1_->mean()) * 0.5f; }

  std::string toString() const override {
    return str("CheckerboardTexture[color0=", color0_->toString(), ", color1=", color1_->toString(), "]");
  }

 private:
  std::shared_ptr<Texture> color0_, color1_;
  UvMapping toUv_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::CheckerboardTexture, Texture, "checkerboard", "Two colours in a checkerboard pattern")
