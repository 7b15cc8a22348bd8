// homogeneous: a medium with constant coefficients. Transmittance is
// exp(-sigma_t d) per channel. Free flights are sampled exactly for one
// channel picked uniformly, and weighted by the one-sample MIS density over
// the three channels (spectral MIS, as Mitsuba 0.6's homogeneous medium):
//   pdf(t) = mean_c sigma_t[c] exp(-sigma_t[c] t),  P(t >= tMax) = mean_c exp(-sigma_t[c] tMax),
// so grey media get weight albedo at a scattering event and 1 otherwise.
//
// | name              | type       | default   | meaning                                           | unit     |
// |-------------------|------------|-----------|---------------------------------------------------|----------|
// | sigma_s, sigma_a  | float/rgb  | -         | scattering / absorption coefficients (0.6 sigmaS) | 1/length |
// | sigma_t, albedo   | float/rgb  | 1, 0.75   | extinction and single-scattering albedo (0.6, M3) | 1/length, - |
// | scale             | float      | 1         | multiplies the coefficients                       | -        |
// | eta               | float      | 1         | refractive index (OPL per unit length)            | -        |
// | (nested) phase    | phase      | isotropic | phase function                                    | -        |
// Give either sigma_s/sigma_a or sigma_t/albedo.
#include <algorithm>
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/medium.h>
#include <femto/render/sampler.h>

namespace femto {
namespace {

/// exp(-sigma * t) with exp(-0 * inf) = 1 (a channel that does not interact).
float transmit(float sigma, float t) { return sigma > 0.0f ? std::exp(-sigma * t) : 1.0f; }
/// 1 - transmit(sigma, t), accurate for small sigma t.
float scatterBefore(float sigma, float t) { return sigma > 0.0f ? -std::expm1(-sigma * t) : 0.0f; }

}  // namespace

class HomogeneousMedium final : public Medium {
 public:
  explicit HomogeneousMedium(const Properties& props) : Medium(props) {
    coefficients_ = readMediumCoefficients(props);
    sigmaT_ = coefficients_.scaledSigmaT();
    sigmaS_ = coefficients_.sigmaS();
  }

  ParameterValues editableParameters() const override {
    return {{"sigma_t", parameterValue(coefficients_.sigmaT)}, {"albedo", parameterValue(coefficients_.albedo)}};
  }
  void setParameter(const std::string& name, const std::vector<double>& value) override {
    if (name == "sigma_t")
      coefficients_.sigmaT = editableColor(toString(), name, value);
    else if (name == "albedo")
      coefficients_.albedo = editableColor(toString(), name, value);
    else
      return Medium::setParameter(name, value);
    sigmaT_ = coefficients_.scaledSigmaT();
    sigmaS_ = coefficients_.sigmaS();
  }

  MediumSample sampleDistance(const Ray& ray, float tMax, Sampler& sampler) const override {
    MediumSample ms;
    ms.t = tMax;
    float uChannel = sampler.next1D(), uDistance = sampler.next1D();
    int channel = std::min(int(uChannel * 3.0f), 2);
    float sigma = sigmaT_[channel];
    float t = sigma > 0.0f ? -std::log1p(-uDistance) / sigma : Infinity;
    if (t < tMax) {
      Color3f tr = transmittance(t);
      float pdf = freeFlightPdf(t);
      ms.scattered = true;
      ms.t = t;
      ms.p = ray(t);
      ms.weight = pdf > 0.0f ? sigmaS_ * tr / pdf : Color3f(0.0f);
    } else {
      Color3f tr = transmittance(tMax);
      float probability = tr.average();
      ms.weight = probability > 0.0f ? tr / probability : Color3f(0.0f);
    }
    return ms;
  }

  /// Conditioned on scattering before `reach`: the channel in proportion to
  /// its probability of scattering before `reach`, the distance from that
  /// channel's exponential truncated there, so the density is
  /// freeFlightPdf(t) / P with P = mean_c (1 - exp(-sigma_t[c] reach)) and the
  /// weight sigma_s T(t) P / freeFlightPdf(t): sampleDistance's estimator
  /// times P(t < reach), every sample inside. Two random numbers, as
  /// sampleDistance.
  MediumSample sampleDistanceBefore(const Ray& ray, float reach, Sampler& sampler) const override {
    MediumSample ms;
    ms.t = reach;
    float uChannel = sampler.next1D(), uDistance = sampler.next1D();
    float channelP[3], total = 0.0f;
    for (int c = 0; c < 3; ++c) total += channelP[c] = scatterBefore(sigmaT_[c], reach);
    if (!(total > 0.0f)) {  // nothing scatters before `reach`
      ms.weight = Color3f(0.0f);
      return ms;
    }
    // The channel in proportion to channelP (the last one with some, should rounding run past the end).
    float target = uChannel * total;
    int channel = 0;
    for (int c = 0; c < 3; ++c) {
      if (!(channelP[c] > 0.0f)) continue;
      channel = c;
      if (target < channelP[c]) break;
      target -= channelP[c];
    }
    float t = -std::log1p(-uDistance * channelP[channel]) / sigmaT_[channel];
    t = std::min(t, std::nextafter(reach, 0.0f));
    float pdf = freeFlightPdf(t);
    ms.scattered = true;
    ms.t = t;
    ms.p = ray(t);
    ms.weight = pdf > 0.0f ? sigmaS_ * transmittance(t) * (total / 3.0f) / pdf : Color3f(0.0f);
    return ms;
  }
  float scatterProbabilityBefore(float reach) const override {
    float p = 0.0f;
    for (int c = 0; c < 3; ++c) p += scatterBefore(sigmaT_[c], reach);
    return p / 3.0f;
  }

  Color3f transmittance(const Ray&, float tMax, Sampler&) const override { return transmittance(tMax); }
  float freeFlightPdf(float t) const override {
    Color3f tr = transmittance(t);
    float pdf = 0.0f;
    for (int c = 0; c < 3; ++c) pdf += sigmaT_[c] * tr[c];
    return pdf / 3.0f;
  }
  Color3f majorant() const override { return sigmaT_; }
  Color3f scatteringCoefficient(const Point3f&) const override { return sigmaS_; }
  bool isHomogeneous() const override { return true; }

  std::string toString() const override {
    return str("HomogeneousMedium[sigma_t=", sigmaT_, ", sigma_s=", sigmaS_, ", ", mediumString(), "]");
  }

 private:
  Color3f transmittance(float t) const {
    return {transmit(sigmaT_.r, t), transmit(sigmaT_.g, t), transmit(sigmaT_.b, t)};
  }

  MediumCoefficients coefficients_;
  Color3f sigmaT_, sigmaS_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::HomogeneousMedium, Medium, "homogeneous", "Medium with constant coefficients")
