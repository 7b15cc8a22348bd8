#pragma once
// Photon beams and camera segments: the two kinds of straight path pieces the
// transient photon-beams estimator pairs up (Jarosz, Nowrouzezahrai, Sadeghi,
// Jensen 2011, "A comprehensive theory of volumetric radiance estimation using
// photon points and beams", sec. 5; made transient by Marco, Jarosz, Gutierrez,
// Jarabo 2017, "Transient Photon Beams").
//
// Time is optical path length (OPL, scene units, see femto/time/time_grid.h).
#include <cstdint>

#include <femto/math/ray.h>
#include <femto/math/spectrum.h>
#include <femto/math/vector.h>

namespace femto {
class Medium;
}

namespace femto::beams {

/// The straight piece of a photon's path between two interactions inside one
/// medium. Light flows from `origin` along `direction`.
struct Beam {
  Point3f origin;        // where the piece starts (emitter, surface or scattering point)
  Vec3f direction;       // unit length, the direction light travels
  float length = 0.0f;   // > 0 and finite: up to the next surface ("long" beam: the photon may scatter
                         // earlier; estimates weight the beam by its transmittance, Jarosz et al. 2011 sec. 5.2)
                         // or to where Russian roulette ended it (estimates divide by the survival
                         // probability, beam_roulette.h)
  Color3f power{0.0f};   // photon power (flux) at `origin`, before attenuation along the beam
  double opl = 0.0;      // OPL at `origin` since emission (emission offset + delays + sum eta*d)
  float eta = 1.0f;      // refractive index of the medium crossed: OPL per unit length
  int16_t depth = 1;     // photon path segments up to and including this one (1: straight from the emitter)
  uint16_t emitter = 0;  // index in Scene::emitters() of the emitter that sent the photon (its pulse)
  const Medium* medium = nullptr;  // the medium the beam crosses (never null for stored beams)
  /// The kernel region's extension before the start and past the end, in
  /// kernel radii, where the beam starts or ends on a boundary of its medium
  /// (boundary_extension.h; 0: none). Estimates there use the density at
  /// the end (T_beam at the clamped parameter) continued by the beam's
  /// attenuation (extensionContinuation).
  float before = 0.0f, after = 0.0f;
  /// Where the beam entered its medium through a pass-through boundary of
  /// another index (light changes speed there but not direction, the
  /// random media family), the wavefront inside is tilted against the beam:
  /// light reaching x beside it crossed the boundary at another point and
  /// arrives at opl + eta s(x) + offsetDelay . (x - origin), offsetDelay =
  /// (eta - eta_before) (n / (n.v) - v) (n: the boundary's normal; ray_beam.cpp,
  /// docs/design/photon-beams.md "Timing the extension before a beam's start").
  /// Zero for every other beam.
  Vec3f offsetDelay{0.0f};
};

/// A camera ray's piece inside one medium: `ray.o + t ray.d`, t in [0, tMax],
/// unit `ray.d` pointing away from the camera (light flows toward ray.o).
struct CameraSegment {
  Ray ray;
  float tMax = 0.0f;
  /// OPL per unit length along the segment: the medium's eta, or 0 when the
  /// camera segment is excluded from time ("observer time" off).
  float eta = 1.0f;
};

}  // namespace femto::beams
