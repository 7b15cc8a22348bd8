// blendbsdf: a linear blend of two BSDFs, (1 - t) f_0 + t f_1, where the
// weight t (a number or a texture, so the blend may vary over the surface)
// is the weight of the SECOND nested BSDF: t = 0 is the first BSDF alone,
// t = 1 the second (Mitsuba 0.6 and Mitsuba 3's `blendbsdf`). A colour
// weight is reduced to the mean of its channels and clamped to [0, 1], as
// Mitsuba does. Sampling picks BSDF 1 with probability t and BSDF 0
// otherwise; smooth samples are weighted by the whole blend (one-sample MIS,
// scattering/bsdf_mixture.h). Any two BSDFs may be blended: reflecting,
// transmitting, delta or pass-through. The nested BSDFs are taken in
// document order.
//
// | name     | type             | default | meaning                                        | unit |
// |----------|------------------|---------|------------------------------------------------|------|
// | weight   | float or texture | 0.5     | weight t of the second BSDF, in [0, 1]         | -    |
// | (nested) | bsdf, exactly 2  | -       | the BSDFs at t = 0 and t = 1, in document order | -   |
#include <array>

#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/render/texture.h>
#include <femto/scattering/bsdf_mixture.h>

namespace femto {

class BlendBSDF final : public BSDF {
 public:
  explicit BlendBSDF(const Properties& props) : weight_(textureOrColor(props, "weight", Color3f(0.5f))) {
    std::vector<ObjectRef> nested = props.objectsOfKind(ObjectKind::BSDF);
    if (nested.size() != 2)
      throw Error(props.location(), str("\"blendbsdf\" takes exactly two nested <bsdf>, got ", nested.size()));
    for (size_t i = 0; i < 2; ++i) bsdfs_[i] = std::dynamic_pointer_cast<BSDF>(nested[i]);
    const float mean = weight_->mean().average();
    if (!(mean >= 0.0f && mean <= 1.0f)) props.raise("weight", str("must lie in [0, 1], got ", weight_->mean()));
  }

  uint32_t flags() const override { return bsdfs_[0]->flags() | bsdfs_[1]->flags(); }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    return sampleMixture(terms(si), si, u1, u2, bs, mode);
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    return evalMixture(terms(si), si, wo, mode);
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    return pdfMixture(terms(si), si, wo, mode);
  }

  std::string toString() const override {
    return str("BlendBSDF[weight=", weight_->toString(), ", bsdfs={", bsdfs_[0]->toString(), ", ",
               bsdfs_[1]->toString(), "}]");
  }

 private:
  /// The two terms at this point: weights and sampling probabilities (1 - t, t).
  std::array<MixtureTerm, 2> terms(const SurfaceInteraction& si) const {
    const float t = std::clamp(weight_->eval(si).average(), 0.0f, 1.0f);
    return {MixtureTerm{bsdfs_[0].get(), 1.0f - t, 1.0f - t}, MixtureTerm{bsdfs_[1].get(), t, t}};
  }

  std::shared_ptr<Texture> weight_;
  std::array<std::shared_ptr<BSDF>, 2> bsdfs_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::BlendBSDF, BSDF, "blendbsdf", "Blend of two BSDFs by a weight or texture")
