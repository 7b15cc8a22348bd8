#include "bsdf_mixture.h"

#include <algorithm>

namespace femto {

Color3f sampleMixture(std::span<const MixtureTerm> terms, const SurfaceInteraction& si, float u1, const Point2f& u2,
                      BSDFSample& bs, TransportMode mode) {
  bs = BSDFSample();
  // Choose term k by u1 and rescale u1 to [0, 1) for the term's own choice.
  size_t k = 0;
  float below = 0.0f;
  while (k + 1 < terms.size() && (terms[k].probability <= 0.0f || u1 >= below + terms[k].probability)) {
    below += terms[k].probability;
    ++k;
  }
  const MixtureTerm& chosen = terms[k];
  if (!(chosen.probability > 0.0f)) return Color3f(0.0f);
  const float u1Reused = std::clamp((u1 - below) / chosen.probability, 0.0f, 0.99999994f);
  Color3f weight = chosen.bsdf->sample(si, u1Reused, u2, bs, mode);
  if (!(bs.pdf > 0.0f)) return Color3f(0.0f);
  if (bs.sampledFlags & BSDFFlags::Delta) {
    bs.pdf *= chosen.probability;
    return weight * (chosen.weight / chosen.probability);
  }
  const float pdf = pdfMixture(terms, si, bs.wo, mode);
  if (!(pdf > 0.0f)) {
    bs.pdf = 0.0f;
    return Color3f(0.0f);
  }
  bs.pdf = pdf;
  return evalMixture(terms, si, bs.wo, mode) / pdf;
}

Color3f evalMixture(std::span<const MixtureTerm> terms, const SurfaceInteraction& si, const Vec3f& wo,
                    TransportMode mode) {
  Color3f f(0.0f);
  for (const MixtureTerm& term : terms)
    if (term.weight > 0.0f) f += term.bsdf->eval(si, wo, mode) * term.weight;
  return f;
}

float pdfMixture(std::span<const MixtureTerm> terms, const SurfaceInteraction& si, const Vec3f& wo,
                 TransportMode mode) {
  float pdf = 0.0f;
  for (const MixtureTerm& term : terms)
    if (term.probability > 0.0f) pdf += term.bsdf->pdf(si, wo, mode) * term.probability;
  return pdf;
}

}  // namespace femto
