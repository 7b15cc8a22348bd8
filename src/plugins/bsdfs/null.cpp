// null: a surface that does not scatter: light passes straight through it
// unchanged (Mitsuba 3's `null`). Useful for shapes that only bound a medium
// or carry an emitter, and as the transparent part of `mask`. The path
// counts its crossing as a delta event, so emitter sampling (which treats the
// surface as an occluder) and BSDF sampling never both find the same light.
//
// No parameters.
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>

namespace femto {

class NullBSDF final : public BSDF {
 public:
  explicit NullBSDF(const Properties&) {}

  uint32_t flags() const override { return BSDFFlags::Null; }

  Color3f sample(const SurfaceInteraction& si, float, const Point2f&, BSDFSample& bs, TransportMode) const override {
    bs = BSDFSample();
    bs.wo = -si.wi;
    bs.pdf = 1.0f;
    bs.sampledFlags = BSDFFlags::Null;
    return Color3f(1.0f);
  }

  Color3f eval(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return Color3f(0.0f); }
  float pdf(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return 0.0f; }

  std::string toString() const override { return "NullBSDF[]"; }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::NullBSDF, BSDF, "null", "Invisible surface: light passes straight through")
