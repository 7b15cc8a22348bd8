// twosided: makes a one-sided reflecting BSDF (diffuse, plastic, conductor,
// ...) reflect on both sides of a surface. With one nested BSDF both sides
// use it; with two, the first is the front (+z) side and the second the
// back. On the back side the directions are mirrored through the tangent
// plane (z -> -z), handed to the nested BSDF as if they were on its front,
// and the sampled direction mirrored back (Mitsuba 3's `twosided`).
// Transmitting BSDFs cannot be nested: they are two-sided already, and
// their interior and exterior differ. Pass-through (`null`, `mask`) may be:
// mirroring commutes with wo = -wi, so it stays pass-through (Mitsuba
// refuses it; accepting it lets twosided wrap a mask as well as the reverse).
//
// | name     | type            | default | meaning                                              | unit |
// |----------|-----------------|---------|------------------------------------------------------|------|
// | (nested) | bsdf, 1 or 2    | -       | front (and back) BSDF, in document order             | -    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>

namespace femto {
namespace {

Vec3f mirrorZ(const Vec3f& v) { return {v.x, v.y, -v.z}; }

}  // namespace

class TwoSidedBSDF final : public BSDF {
 public:
  explicit TwoSidedBSDF(const Properties& props) {
    std::vector<ObjectRef> nested = props.objectsOfKind(ObjectKind::BSDF);
    if (nested.empty() || nested.size() > 2)
      throw Error(props.location(), str("\"twosided\" takes one or two nested <bsdf>, got ", nested.size()));
    front_ = std::dynamic_pointer_cast<BSDF>(nested.front());
    back_ = std::dynamic_pointer_cast<BSDF>(nested.back());
    for (const auto& bsdf : {front_, back_})
      if (bsdf->flags() & BSDFFlags::Transmission & ~uint32_t(BSDFFlags::Null))
        throw Error(props.location(), str("\"twosided\" cannot wrap a transmitting BSDF (", bsdf->toString(),
                                          "); it scatters on both sides already"));
  }

  uint32_t flags() const override { return front_->flags() | back_->flags(); }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    if (Frame::cosTheta(si.wi) >= 0.0f) return front_->sample(si, u1, u2, bs, mode);
    Color3f weight = back_->sample(mirrored(si), u1, u2, bs, mode);
    bs.wo = mirrorZ(bs.wo);
    return weight;
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    if (Frame::cosTheta(si.wi) >= 0.0f) return front_->eval(si, wo, mode);
    return back_->eval(mirrored(si), mirrorZ(wo), mode);
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    if (Frame::cosTheta(si.wi) >= 0.0f) return front_->pdf(si, wo, mode);
    return back_->pdf(mirrored(si), mirrorZ(wo), mode);
  }

  std::string toString() const override {
    return str("TwoSidedBSDF[front=", front_->toString(), ", back=", back_->toString(), "]");
  }

 private:
  /// The interaction as the back BSDF sees it: wi on its front side.
  static SurfaceInteraction mirrored(const SurfaceInteraction& si) {
    SurfaceInteraction flipped = si;
    flipped.wi = mirrorZ(si.wi);
    return flipped;
  }

  std::shared_ptr<BSDF> front_, back_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::TwoSidedBSDF, BSDF, "twosided", "Two-sided wrapper for reflecting BSDFs")
