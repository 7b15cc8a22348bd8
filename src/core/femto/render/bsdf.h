#pragma once
// Bidirectional scattering distribution functions, in the local shading frame
// (normal = +z). Convention (as Mitsuba 3): si.wi points toward the viewer,
// `wo` toward the light; eval returns f(wi, wo) * |cos(wo)|.
#include <cstdint>

#include <femto/core/object.h>
#include <femto/render/interaction.h>
#include <femto/time/scattering_delay.h>
#include <femto/math/spectrum.h>

namespace femto {

enum class TransportMode { Radiance, Importance };

namespace BSDFFlags {
enum : uint32_t {
  None = 0,
  Null = 1u << 0,                 // passes light straight through (index-matched boundary)
  DiffuseReflection = 1u << 1,
  DiffuseTransmission = 1u << 2,
  GlossyReflection = 1u << 3,
  GlossyTransmission = 1u << 4,
  DeltaReflection = 1u << 5,
  DeltaTransmission = 1u << 6,
  Delta = Null | DeltaReflection | DeltaTransmission,
  Smooth = DiffuseReflection | DiffuseTransmission | GlossyReflection | GlossyTransmission,
  Transmission = Null | DiffuseTransmission | GlossyTransmission | DeltaTransmission,
};
}

struct BSDFSample {
  Vec3f wo;               // sampled direction, local frame
  float pdf = 0.0f;       // solid-angle density; for a delta component the probability of choosing it
  float eta = 1.0f;       // relative IOR crossed (1 unless refracted)
  uint32_t sampledFlags = 0;
};

class BSDF : public Object {
 public:
  ObjectKind kind() const override { return ObjectKind::BSDF; }
  /// Union of BSDFFlags of all components.
  virtual uint32_t flags() const = 0;
  /// Sample `wo`; returns f * |cos wo| / pdf, or black on failure (then bs.pdf == 0).
  virtual Color3f sample(const SurfaceInteraction& si, float u1, const Point2f& u2, BSDFSample& bs,
                         TransportMode mode = TransportMode::Radiance) const = 0;
  /// f(wi, wo) * |cos wo| for the non-delta components.
  virtual Color3f eval(const SurfaceInteraction& si, const Vec3f& wo,
                       TransportMode mode = TransportMode::Radiance) const = 0;
  /// Solid-angle density with which sample() picks `wo` (non-delta components).
  virtual float pdf(const SurfaceInteraction& si, const Vec3f& wo,
                    TransportMode mode = TransportMode::Radiance) const = 0;

  bool hasSmooth() const { return (flags() & BSDFFlags::Smooth) != 0; }
  bool isDeltaOnly() const { return (flags() & BSDFFlags::Smooth) == 0; }

  /// Every BSDF takes `delay` and `lifetime` (time/scattering_delay.h):
  /// time spent in each scattering event at the surface (0 by default).
  void readCommonParameters(const Properties& props) override { delay_ = ScatteringDelay(props); }
  bool hasDelay() const { return delay_.any(); }
  /// Extra optical path length of one scattering event, from u in [0, 1).
  double sampleDelay(float u) const { return delay_.sample(u); }

 private:
  ScatteringDelay delay_;
};

/// An index-matched boundary (no BSDF, or a null one): paths cross it
/// straight on and it only changes the medium (transport/volumetric.h).
inline bool isPassThrough(const BSDF* bsdf) { return !bsdf || bsdf->flags() == BSDFFlags::Null; }

}  // namespace femto
