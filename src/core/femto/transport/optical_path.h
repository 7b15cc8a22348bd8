#pragma once
// Where a transient path is, in space and in time: the part of a camera path
// or photon that transient_path and transient_beams' tracers share. A segment
// adds eta times its length to the optical path length (OPL,
// time/time_grid.h), where eta is the refractive index of the medium crossed
// or, where there is no medium, that of the dielectric the path is inside
// (the product of the relative IORs of the refractions so far,
// BSDFSample::eta). Lengths are measured between exact vertices: the ray's
// origin may be offset off a surface, which must not shorten the OPL.
#include <cmath>

#include <femto/math/ray.h>
#include <femto/math/vector.h>
#include <femto/render/interaction.h>
#include <femto/render/medium.h>
#include <femto/transport/volumetric.h>

namespace femto {

struct OpticalPath {
  Ray ray;                         // ray.o may be offset off a surface; `vertex` is exact
  Point3f vertex;                  // where the current segment starts (sensor, emitter, scattering or boundary point)
  double opl = 0.0;                // OPL at `vertex`
  const Medium* medium = nullptr;  // the medium `ray` travels through (none: vacuum or a dielectric)
  float surfaceEta = 1.0f;         // refractive index where there is no medium

  /// The refractive index along the current segment.
  float eta() const { return medium ? medium->eta() : surfaceEta; }
  /// The OPL of the current segment from `vertex` to `p`.
  double segmentOpl(const Point3f& p) const { return double(eta()) * distance(vertex, p); }
  /// Move to vertex `p` along the current segment, adding its OPL when
  /// `counted` (see segmentCounts); false once the OPL is no longer finite.
  bool advance(const Point3f& p, bool counted = true) {
    if (counted) opl += segmentOpl(p);
    vertex = p;
    return std::isfinite(opl);
  }
  /// Continue straight on through `si`, an index-matched boundary
  /// (isPassThrough), maybe into another medium.
  void crossBoundary(const SurfaceInteraction& si) {
    medium = mediumAfter(si, ray.d, medium);
    ray = si.spawnRay(ray.d);
  }
  /// Leave surface `si` in world direction `wo`, sampled from its BSDF with
  /// relative IOR `relativeEta` (BSDFSample::eta: entering a dielectric
  /// multiplies by int/ext, leaving by ext/int; 1 for reflection).
  void leaveSurface(const SurfaceInteraction& si, const Vec3f& wo, float relativeEta) {
    surfaceEta *= relativeEta;
    medium = mediumAfter(si, wo, medium);
    ray = si.spawnRay(wo);
  }
};

/// Whether a camera path's segment adds to its OPL: with observer time off,
/// the camera segment (sensor to the first scattering vertex) does not, so
/// wavefronts show where light is rather than when the camera sees it
/// (Marco et al., "Transient Photon Beams", fig. "with and without observer time").
inline bool segmentCounts(bool observerTime, bool cameraSegment) { return observerTime || !cameraSegment; }

}  // namespace femto
