// mixturebsdf: a linear combination sum_i w_i f_i of any number of BSDFs
// with constant weights (Mitsuba 0.6's `mixturebsdf`). The weights must not
// be negative and must sum to more than zero; when they sum to less than
// one the surface absorbs the rest. When they sum to more than one they are
// divided by their sum, with a warning, as Mitsuba 0.6 does (its BSDF
// parameter `ensureEnergyConservation`, true by default; false keeps them as
// given). Sampling picks BSDF i with probability w_i / sum_j w_j; smooth
// samples are weighted by the whole mixture (one-sample MIS,
// scattering/bsdf_mixture.h). The i-th weight belongs to the i-th nested
// BSDF in document order.
//
// | name                       | type    | default | meaning                                          | unit |
// |----------------------------|---------|---------|--------------------------------------------------|------|
// | weights                    | string  | -       | the weights, separated by commas, spaces or ';' (required) | - |
// | ensure_energy_conservation | boolean | true    | divide weights that sum above 1 by their sum     | -    |
// | (nested)                   | bsdf    | -       | as many BSDFs as weights, in document order      | -    |
#include <cstdlib>

#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/bsdf_mixture.h>

namespace femto {
namespace {

/// Mitsuba's list syntax: numbers separated by any of " ,;".
std::vector<float> parseWeights(const Properties& props) {
  if (!props.has("weights")) throw Error(props.location(), "\"mixturebsdf\" needs a <string name=\"weights\">");
  const std::string text = props.getString("weights");
  std::vector<float> weights;
  size_t pos = 0;
  while ((pos = text.find_first_not_of(" ,;\t\n", pos)) != std::string::npos) {
    const size_t end = std::min(text.find_first_of(" ,;\t\n", pos), text.size());
    const std::string token = text.substr(pos, end - pos);
    char* rest = nullptr;
    const double w = std::strtod(token.c_str(), &rest);
    if (*rest != '\0') props.raise("weights", str("could not read \"", token, "\" as a number"));
    if (!(w >= 0.0)) props.raise("weights", str("must not be negative, got ", token));
    weights.push_back(float(w));
    pos = end;
  }
  if (weights.empty()) props.raise("weights", "no weights given");
  return weights;
}

}  // namespace

class MixtureBSDF final : public BSDF {
 public:
  explicit MixtureBSDF(const Properties& props) {
    std::vector<float> weights = parseWeights(props);
    const bool ensureEnergyConservation = props.getBool("ensure_energy_conservation", true);
    std::vector<ObjectRef> nested = props.objectsOfKind(ObjectKind::BSDF);
    if (nested.size() != weights.size())
      props.raise("weights", str("gives ", weights.size(), " weights for ", nested.size(), " nested <bsdf>"));
    float total = 0.0f;
    for (float w : weights) total += w;
    if (!(total > 0.0f)) props.raise("weights", "must sum to more than zero");
    if (ensureEnergyConservation && total > 1.0f) {
      const SourceLocation where = props.location("weights");
      logWarn(where.known() ? where.toString() + ": " : std::string(), "mixturebsdf: the weights sum to ", total,
              " > 1 and are divided by it (ensure_energy_conservation=false keeps them)");
      for (float& w : weights) w /= total;
      total = 1.0f;
    }
    for (size_t i = 0; i < nested.size(); ++i) {
      bsdfs_.push_back(std::dynamic_pointer_cast<BSDF>(nested[i]));
      terms_.push_back(MixtureTerm{bsdfs_.back().get(), weights[i], weights[i] / total});
      flags_ |= bsdfs_.back()->flags();
    }
  }

  uint32_t flags() const override { return flags_; }

  Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                 TransportMode mode) const override {
    return sampleMixture(terms_, si, u1, u2, bs, mode);
  }

  Color3f eval(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    return evalMixture(terms_, si, wo, mode);
  }

  float pdf(const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode) const override {
    return pdfMixture(terms_, si, wo, mode);
  }

  std::string toString() const override {
    std::string text = "MixtureBSDF[weights={";
    for (size_t i = 0; i < terms_.size(); ++i) text += str(i ? ", " : "", terms_[i].weight);
    text += "}, bsdfs={";
    for (size_t i = 0; i < bsdfs_.size(); ++i) text += str(i ? ", " : "", bsdfs_[i]->toString());
    return text + "}]";
  }

 private:
  std::vector<std::shared_ptr<BSDF>> bsdfs_;
  std::vector<MixtureTerm> terms_;  // points into bsdfs_
  uint32_t flags_ = 0;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::MixtureBSDF, BSDF, "mixturebsdf", "Weighted sum of any number of BSDFs")
