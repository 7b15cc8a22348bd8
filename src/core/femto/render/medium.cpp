#include <femto/render/medium.h>

#include <cmath>

#include <femto/render/default_child.h>

namespace femto {

MediumCoefficients readMediumCoefficients(const Properties& props, bool sigmaTIsVolume, bool albedoIsVolume) {
  MediumCoefficients c;
  // has() also records the names as the plugin's vocabulary for "did you mean" hints.
  bool scatteringForm = props.has("sigma_s") || props.has("sigma_a");
  bool extinctionForm = (!sigmaTIsVolume && props.has("sigma_t")) || (!albedoIsVolume && props.has("albedo"));
  if (scatteringForm && extinctionForm) {
    const char* which = props.has("sigma_s") ? "sigma_s" : "sigma_a";
    props.raise(which, "give either sigma_s/sigma_a or sigma_t/albedo, not both");
  }
  auto requireValid = [&](const char* name, const Color3f& v) {
    if (!v.isValid()) props.raise(name, str("must be finite and non-negative, got ", v));
  };
  if (scatteringForm) {
    Color3f sigmaS = props.getColor("sigma_s", Color3f(0.0f)), sigmaA = props.getColor("sigma_a", Color3f(0.0f));
    requireValid("sigma_s", sigmaS);
    requireValid("sigma_a", sigmaA);
    c.sigmaT = sigmaS + sigmaA;
    for (int i = 0; i < 3; ++i) c.albedo[i] = c.sigmaT[i] > 0.0f ? sigmaS[i] / c.sigmaT[i] : 0.0f;
  } else {
    if (!sigmaTIsVolume) c.sigmaT = props.getColor("sigma_t", c.sigmaT);
    if (!albedoIsVolume) c.albedo = props.getColor("albedo", c.albedo);
    requireValid("sigma_t", c.sigmaT);
    requireValid("albedo", c.albedo);
    if (c.albedo.maxValue() > 1.0f) props.raise("albedo", str("must lie in [0, 1], got ", c.albedo));
  }
  c.scale = props.getFloat("scale", 1.0f, Range::nonNegative());
  return c;
}

Medium::Medium(const Properties& props)
    : phase_(nestedOrDefault<PhaseFunction>(props, ObjectKind::PhaseFunction, "isotropic")),
      eta_(props.getFloat("eta", 1.0f, Range::atLeast(1), "a refractive index")) {
}

Medium::~Medium() = default;

Color3f Medium::scatteringCoefficient(const Point3f&) const {
  throw Error(str(toString(), " does not report its scattering coefficient (needed by density estimators such as "
                              "transient_beams)"));
}

float Medium::freeFlightPdf(float) const {
  throw Error(str(toString(), " has no closed-form free-flight density (only homogeneous media do)"));
}

MediumSample Medium::sampleDistanceBefore(const Ray& ray, float reach, Sampler& sampler) const {
  MediumSample ms = sampleDistance(ray, reach, sampler);
  if (!ms.scattered) ms.weight = Color3f(0.0f);
  return ms;
}

float Medium::scatterProbabilityBefore(float) const {
  throw Error(str(toString(), " has no closed-form probability of scattering before a distance (only homogeneous media do)"));
}

std::string Medium::mediumString() const { return str("eta=", eta_, ", phase=", phase_->toString()); }

}  // namespace femto
