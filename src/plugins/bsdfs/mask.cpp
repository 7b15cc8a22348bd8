// mask: cut-outs (leaves, fences): a blend of a nested BSDF, weighted by
// `opacity`, and the `null` BSDF (straight pass-through), weighted by
// 1 - opacity (Mitsuba 3's `mask`). sample() passes through with probability
// 1 - opacity and otherwise samples the nested BSDF, so both choices keep
// their natural weights; eval and pdf scale the nested ones by the opacity.
// A colour opacity is reduced to the mean of its channels (opacity is a
// single probability).
//
// | name     | type             | default | meaning                                     | unit |
// |----------|------------------|---------|---------------------------------------------|------|
// | opacity  | float or texture | 0.5     | fraction of light the nested BSDF scatters  | -    |
// | (nested) | bsdf             | -       | the BSDF of the opaque part (required)      | -    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/render/texture.h>

namespace femto {

class MaskBSDF final : public BSDF {
 public:
  explicit MaskBSDF(const Properties& props)
      : opacity_(textureOrColor(props, "opacity", Color3f(0.5f))), nested_(props.object<BSDF>(ObjectKind::BSDF)) {
    if (!nested_) throw Error(props.location(), "\"mask\" needs a nested <bsdf> for its opaque part");
    Color3f mean = opacity_->mean();
    for (int c = 0; c < 3; ++c)
      if (!(mean[c] >= 0.0f && mean[c] <= 1.0f))
        props.raise("opacity", str("must lie in [0, 1], got ", mean));
  }

  uint32_t flags() const override { return nested_->flags() | BSDFFlags::Null; }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    const float alpha = opacity(si);
    if (u1 >= alpha) {  // pass through, with probability 1 - opacity: weight (1 - a) / (1 - a)
      bs = BSDFSample();
      bs.wo = -si.wi;
      bs.pdf = 1.0f - alpha;
      bs.sampledFlags = BSDFFlags::Null;
      return Color3f(1.0f);
    }
    // Reuse u1, rescaled to [0, 1), for the nested BSDF's own choice.
    Color3f weight = nested_->sample(si, u1 / alpha, u2, bs, mode);
    bs.pdf *= alpha;
    return weight;
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    return nested_->eval(si, wo, mode) * opacity(si);
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    return nested_->pdf(si, wo, mode) * opacity(si);
  }

  std::string toString() const override {
    return str("MaskBSDF[opacity=", opacity_->toString(), ", bsdf=", nested_->toString(), "]");
  }

 private:
  float opacity(const SurfaceInteraction& si) const { return std::clamp(opacity_->eval(si).average(), 0.0f, 1.0f); }

  std::shared_ptr<Texture> opacity_;
  std::shared_ptr<BSDF> nested_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::MaskBSDF, BSDF, "mask", "Opacity mask: blends a BSDF with pass-through")
