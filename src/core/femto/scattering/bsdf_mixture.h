#pragma once
// A weighted sum of BSDFs, f = sum_i w_i f_i, sampled by choosing BSDF i with
// probability p_i and drawing a direction from it (one-sample MIS over the
// terms, Mitsuba 0.6's blendbsdf and mixturebsdf). The weights need not be
// the probabilities: mixturebsdf's weights may sum to less than one (the
// rest is absorbed) while it picks a term by the normalised weights.
//
// A smooth sample is weighted by the whole mixture, sum_i w_i f_i / sum_i
// p_i pdf_i, so sample(), eval() and pdf() agree however the lobes of the
// terms overlap. A delta sample keeps the weight of the term that drew it,
// scaled by w_k / p_k: no other term reaches that direction.
#include <span>

#include <femto/render/bsdf.h>

namespace femto {

struct MixtureTerm {
  const BSDF* bsdf = nullptr;
  float weight = 0.0f;       // w_i, the factor on f_i
  float probability = 0.0f;  // p_i, the chance of sampling term i (the p_i sum to 1)
};

Color3f sampleMixture(std::span<const MixtureTerm> terms, const SurfaceInteraction& si, float u1, const Point2f& u2,
                      BSDFSample& bs, TransportMode mode);
Color3f evalMixture(std::span<const MixtureTerm> terms, const SurfaceInteraction& si, const Vec3f& wo,
                    TransportMode mode);
float pdfMixture(std::span<const MixtureTerm> terms, const SurfaceInteraction& si, const Vec3f& wo, TransportMode mode);

}  // namespace femto
