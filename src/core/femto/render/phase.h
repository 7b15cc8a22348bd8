#pragma once
// Phase functions: the angular distribution of light scattered in a medium.
// Convention (as Mitsuba 3 and pbrt): both directions point away from the
// scattering point; `wi` toward where the light goes after scattering when
// tracing from the camera (i.e. -ray.d, back toward the previous vertex),
// `wo` toward the next vertex or the light. Directions are world space and
// unit length; values are densities over the unit sphere (integrate to 1).
//
// Scattering may take time (fluorescence-like lifetimes, transient RTE of
// Marco et al., "Transient Photon Beams", eq. 2): every phase function reads
// `delay` and `lifetime` (time/scattering_delay.h).
#include <femto/core/object.h>
#include <femto/core/properties.h>
#include <femto/math/vector.h>
#include <femto/time/scattering_delay.h>

namespace femto {

class PhaseFunction : public Object {
 public:
  /// Reads "delay" and "lifetime" (see the table above).
  explicit PhaseFunction(const Properties& props);
  ObjectKind kind() const override { return ObjectKind::PhaseFunction; }

  /// Density p(wi, wo) over the sphere of directions `wo`.
  virtual float eval(const Vec3f& wi, const Vec3f& wo) const = 0;
  /// Sample `wo` from u in [0,1)^2; returns eval / pdf (1 for perfectly
  /// importance-sampled phase functions) and the density in `pdf`.
  virtual float sample(const Vec3f& wi, const Point2f& u, Vec3f& wo, float& pdf) const = 0;
  /// Density with which sample() picks `wo`.
  virtual float pdf(const Vec3f& wi, const Vec3f& wo) const = 0;

  /// Extra optical path length spent in one scattering event, from u in [0,1):
  /// delay + an exponential variate of mean lifetime (0 by default).
  virtual double sampleDelay(float u) const;
  /// Does scattering take time at all? (Integrators skip sampleDelay otherwise.)
  bool hasDelay() const { return delay_.any(); }

 protected:
  /// "delay=..., lifetime=..." for toString() of derived classes ("" when both are 0).
  std::string delayString() const;

 private:
  ScatteringDelay delay_;
};

}  // namespace femto
