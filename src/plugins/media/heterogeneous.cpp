// heterogeneous: a medium whose extinction varies in space,
//   sigma_t(x) = scale * sigma_t * density(x),  sigma_s(x) = sigma_t(x) * albedo(x),
// with density(x) from a nested <volume> (Mitsuba 0.6: name="density";
// Mitsuba 3: name="sigma_t"), usually a "gridvolume".
//
// Both estimators use the majorant m = max over space and channels of
// sigma_t(x) (grid maximum times the largest channel) and tentative
// collisions at rate m, clipped to the volume's bounding box:
//  - transmittance: ratio tracking (Novak et al. 2014, "Residual ratio
//    tracking", sec. 3), the product of (1 - sigma_t(x_i) / m) per channel;
//  - free flights: spectral tracking (Kutz et al. 2017, "Spectral and
//    decomposition tracking", sec. 5) with history-aware probabilities of
//    scattering vs. null collisions, which reduces to delta tracking with
//    albedo weighting for grey media and stays unbiased for chromatic ones.
//
// | name              | type             | default   | meaning                                        | unit     |
// |-------------------|------------------|-----------|------------------------------------------------|----------|
// | density           | volume           | -         | density field (Mitsuba 0.6)                    | -        |
// | sigma_t           | float/rgb/volume | 1         | extinction multiplier, or the field (Mitsuba 3)| 1/length |
// | albedo            | float/rgb/volume | 0.75      | single-scattering albedo                       | -        |
// | sigma_s, sigma_a  | float/rgb        | -         | instead of sigma_t/albedo (0.6 sigmaS/sigmaA)  | 1/length |
// | scale             | float            | 1         | multiplies the coefficients                    | -        |
// | eta               | float            | 1         | refractive index (OPL per unit length)         | -        |
// | (nested) phase    | phase            | isotropic | phase function                                 | -        |
#include <algorithm>
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/medium.h>
#include <femto/render/sampler.h>
#include <femto/render/volume.h>

namespace femto {
namespace {

bool isVolume(const Properties& props, const char* name) {
  return props.has(name) && props.type(name) == Properties::Type::Object;
}

std::shared_ptr<Volume> volumeParam(const Properties& props, const char* name) {
  auto volume = std::dynamic_pointer_cast<Volume>(props.getObject(name));
  if (!volume) props.raise(name, "expected a <volume>");
  return volume;
}

/// Parameter range [t0, t1] of `ray` inside `box` intersected with [0, tMax]
/// (slab method); false when they do not overlap. An invalid box is unbounded.
bool clipToBox(const Ray& ray, const BoundingBox3f& box, float tMax, float& t0, float& t1) {
  t0 = 0.0f;
  t1 = tMax;
  if (!box.valid()) return true;
  for (int a = 0; a < 3; ++a) {
    float inv = 1.0f / ray.d[a];
    float near = (box.min[a] - ray.o[a]) * inv, far = (box.max[a] - ray.o[a]) * inv;
    if (near > far) std::swap(near, far);
    if (std::isnan(near) || std::isnan(far)) {  // parallel to the slab and on its boundary plane
      if (ray.o[a] < box.min[a] || ray.o[a] > box.max[a]) return false;
      continue;
    }
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
  }
  return t0 <= t1;
}

}  // namespace

class HeterogeneousMedium final : public Medium {
 public:
  explicit HeterogeneousMedium(const Properties& props) : Medium(props) {
    bool sigmaTVolume = isVolume(props, "sigma_t");
    if (sigmaTVolume && props.has("density"))
      props.raise("sigma_t", "give the density field either as \"density\" or as a \"sigma_t\" volume, not both");
    if (!sigmaTVolume && !isVolume(props, "density"))
      props.raise(props.has("density") ? "density" : "sigma_t",
                  "a heterogeneous medium needs a density field: a nested <volume name=\"density\"> (Mitsuba 0.6) "
                  "or <volume name=\"sigma_t\"> (Mitsuba 3)");
    density_ = volumeParam(props, sigmaTVolume ? "sigma_t" : "density");
    if (isVolume(props, "albedo")) albedoVolume_ = volumeParam(props, "albedo");
    MediumCoefficients c = readMediumCoefficients(props, sigmaTVolume, albedoVolume_ != nullptr);
    sigmaT_ = c.scaledSigmaT();
    albedo_ = c.albedo;
    if (density_->maxFloat() < 0.0f) props.raise(sigmaTVolume ? "sigma_t" : "density", "density must not be negative");
    majorant_ = sigmaT_.maxValue() * density_->maxFloat();
  }

  MediumSample sampleDistance(const Ray& ray, float tMax, Sampler& sampler) const override {
    MediumSample ms;
    ms.t = tMax;
    float t, t1;
    if (!(majorant_ > 0.0f) || !clipToBox(ray, density_->bbox(), tMax, t, t1)) return ms;
    t -= std::log1p(-sampler.next1D()) / majorant_;
    return trackFrom(ray, t, t1, Color3f(1.0f), ms, sampler);
  }

  /// Conditioned on the first tentative collision falling before `reach`:
  /// only paths with one there can scatter before `reach`, so sampling it
  /// from the majorant's exponential truncated at `reach` (inside the box)
  /// and weighting by its probability P = 1 - exp(-m (reach - t0)) keeps
  /// sampleDistance's expectation for scattering events before `reach`
  /// (the same conditioning as the homogeneous medium's, on the tentative
  /// collision; for a constant density it is that of the homogeneous medium
  /// in grey). Later tentative collisions are unconditioned: a path whose
  /// null collisions carry it past `reach` gets weight zero.
  MediumSample sampleDistanceBefore(const Ray& ray, float reach, Sampler& sampler) const override {
    MediumSample ms;
    ms.t = reach;
    ms.weight = Color3f(0.0f);
    float t, t1;
    if (!(majorant_ > 0.0f) || !clipToBox(ray, density_->bbox(), reach, t, t1)) return ms;
    float probability = -std::expm1(-majorant_ * (t1 - t));
    if (!(probability > 0.0f)) return ms;
    t = std::min(t - std::log1p(-sampler.next1D() * probability) / majorant_, std::nextafter(t1, 0.0f));
    ms = trackFrom(ray, t, t1, Color3f(probability), ms, sampler);
    if (!ms.scattered) ms.weight = Color3f(0.0f);
    return ms;
  }

  Color3f transmittance(const Ray& ray, float tMax, Sampler& sampler) const override {
    float t, t1;
    if (!(majorant_ > 0.0f) || !clipToBox(ray, density_->bbox(), tMax, t, t1)) return Color3f(1.0f);
    Color3f tr(1.0f);
    for (;;) {
      t -= std::log1p(-sampler.next1D()) / majorant_;
      if (!(t < t1)) break;
      tr *= Color3f(1.0f) - sigmaT_ * (density_->evalFloat(ray(t)) / majorant_);
      if (tr.isBlack()) break;
    }
    return tr;
  }

  Color3f majorant() const override { return sigmaT_ * density_->maxFloat(); }
  Color3f scatteringCoefficient(const Point3f& p) const override {
    return sigmaT_ * density_->evalFloat(p) * albedoAt(p);
  }

  std::string toString() const override {
    return str("HeterogeneousMedium[sigma_t=", sigmaT_, ", density=", density_->toString(), ", albedo=",
               albedoVolume_ ? albedoVolume_->toString() : str(albedo_), ", ", mediumString(), "]");
  }

 private:
  Color3f albedoAt(const Point3f& p) const { return albedoVolume_ ? albedoVolume_->evalColor(p) : albedo_; }

  /// Spectral tracking from a tentative collision at `t` (none when t >= t1,
  /// the end of the segment in the box) carrying `weight`: scatter or pass
  /// the null collision with history-aware probabilities (Kutz et al. 2017,
  /// sec. 5.2: the mean over channels of the current weight times each
  /// coefficient), then the next tentative collision at rate m. `ms` holds
  /// the crossing's t (the segment's end).
  MediumSample trackFrom(const Ray& ray, float t, float t1, Color3f weight, MediumSample ms, Sampler& sampler) const {
    for (;; t -= std::log1p(-sampler.next1D()) / majorant_) {
      if (!(t < t1)) break;
      Point3f p = ray(t);
      Color3f sigmaT = sigmaT_ * density_->evalFloat(p);
      Color3f sigmaS = sigmaT * albedoAt(p);
      Color3f sigmaN = Color3f(majorant_) - sigmaT;  // null-collision coefficient, >= 0 by the majorant
      float scatter = (weight * sigmaS).average(), null = (weight * sigmaN).average();
      if (!(scatter + null > 0.0f)) {  // purely absorbing here: the path carries nothing further
        ms.weight = Color3f(0.0f);
        return ms;
      }
      float pScatter = scatter / (scatter + null);
      if (sampler.next1D() < pScatter) {
        ms.scattered = true;
        ms.t = t;
        ms.p = p;
        ms.weight = weight * sigmaS / (majorant_ * pScatter);
        return ms;
      }
      weight = weight * sigmaN / (majorant_ * (1.0f - pScatter));
    }
    ms.weight = weight;
    return ms;
  }

  std::shared_ptr<Volume> density_, albedoVolume_;
  Color3f sigmaT_, albedo_;
  float majorant_ = 0.0f;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::HeterogeneousMedium, Medium, "heterogeneous", "Medium with a spatially varying density")
