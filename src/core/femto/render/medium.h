#pragma once
// Participating media. A medium fills the space between surfaces that name it
// (shape refs "interior"/"exterior", or the sensor's "medium"). Along a ray
// segment it samples free-flight distances (where light scatters) and
// estimates transmittance; it also carries its phase function and its
// refractive index, which scales the optical path length (OPL) of light
// crossing it (transient RTE, Marco et al. "Transient Photon Beams", eq. 3).
//
// Every medium reads (Medium's constructor):
//
// | name  | type  | default   | meaning                                     | unit |
// |-------|-------|-----------|---------------------------------------------|------|
// | eta   | float | 1         | refractive index: OPL per unit distance     | -    |
// | phase | phase | isotropic | nested <phase> (the single one, any name)   | -    |
//
// Segments are `ray.o + t ray.d` for t in [0, tMax] with unit `ray.d`
// (ray.tmin is ignored); tMax may be Infinity (a ray escaping the scene).
#include <memory>

#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/math/ray.h>
#include <femto/render/phase.h>
#include <femto/math/spectrum.h>

namespace femto {

class Sampler;

/// Outcome of free-flight sampling along one segment.
struct MediumSample {
  bool scattered = false;  // a real scattering event happened at `t` (< tMax)
  float t = 0.0f;          // distance of the event; tMax when the segment was crossed
  Point3f p;               // ray(t) for scattering events
  /// Throughput factor: sigma_s(t) T(0, t) / pdf(t) at a scattering event,
  /// T(0, tMax) / P(no event) when the segment was crossed. Zero: the path was absorbed.
  Color3f weight{1.0f};
};

/// Extinction and single-scattering albedo, read in any of the spellings
/// scenes use: sigma_s/sigma_a (Mitsuba 0.6 "sigmaS"/"sigmaA", upgraded by the
/// loader) or sigma_t/albedo (Mitsuba 0.6 "sigmaT", Mitsuba 3); both forms at
/// once is an error. "scale" multiplies the coefficients.
struct MediumCoefficients {
  Color3f sigmaT{1.0f};
  Color3f albedo{0.75f};  // Mitsuba's default albedo
  float scale = 1.0f;
  Color3f sigmaS() const { return sigmaT * albedo * scale; }
  Color3f scaledSigmaT() const { return sigmaT * scale; }
};

/// Read MediumCoefficients from `props`. `sigmaTIsVolume`/`albedoIsVolume`
/// skip a parameter a heterogeneous medium gets as a nested <volume> instead.
MediumCoefficients readMediumCoefficients(const Properties& props, bool sigmaTIsVolume = false,
                                          bool albedoIsVolume = false);

class Medium : public Object {
 public:
  /// Reads "eta" and the nested phase function (default isotropic).
  explicit Medium(const Properties& props);
  ~Medium() override;
  ObjectKind kind() const override { return ObjectKind::Medium; }

  /// Sample where light traced along `ray` first scatters within [0, tMax].
  virtual MediumSample sampleDistance(const Ray& ray, float tMax, Sampler& sampler) const = 0;
  /// Transmittance T(0, tMax) along `ray` (exact, or an unbiased estimate
  /// such as ratio tracking for heterogeneous media).
  virtual Color3f transmittance(const Ray& ray, float tMax, Sampler& sampler) const = 0;
  /// Upper bound of the extinction coefficient sigma_t anywhere in the medium
  /// (per channel), the majorant of delta/ratio tracking.
  virtual Color3f majorant() const = 0;
  /// Scattering coefficient sigma_s at `p` (density estimators such as photon
  /// beams evaluate it where a camera ray meets a beam). The default throws
  /// femto::Error naming the medium.
  virtual Color3f scatteringCoefficient(const Point3f& p) const;
  /// Constant coefficients (transmittance needs no random numbers).
  virtual bool isHomogeneous() const { return false; }
  /// Density with which sampleDistance reports a scattering event at
  /// distance t (< tMax) along a ray, for MIS against other distance sampling
  /// (transport/equiangular.h). Homogeneous media only (isHomogeneous()); the
  /// default, for tracking in heterogeneous media that has no closed form, throws.
  virtual float freeFlightPdf(float t) const;
  /// A free flight along `ray` that only matters if it scatters before
  /// `reach` (time gating: past it no light arrives in the film's window,
  /// transport/time_gate.h): the scattering events of sampleDistance(ray,
  /// reach) in expectation, with the samples that would have crossed
  /// [0, reach) removed where the medium can (conditioned on an event before
  /// `reach`, weighted by its probability). A path that still crosses gets
  /// weight zero. The default tracks up to `reach` and zeroes crossings.
  virtual MediumSample sampleDistanceBefore(const Ray& ray, float reach, Sampler& sampler) const;
  /// The probability with which sampleDistanceBefore conditions, when it
  /// has a closed form (homogeneous media: free flights' chance to scatter
  /// before `reach`, whose density is then freeFlightPdf(t) / it). The
  /// default throws, as freeFlightPdf.
  virtual float scatterProbabilityBefore(float reach) const;

  const PhaseFunction& phase() const { return *phase_; }
  /// Refractive index: light crossing distance d adds eta * d to its OPL.
  float eta() const { return eta_; }

 protected:
  /// "eta=..., phase=..." for toString() of derived classes.
  std::string mediumString() const;

 private:
  std::shared_ptr<PhaseFunction> phase_;
  float eta_ = 1.0f;
};

}  // namespace femto
