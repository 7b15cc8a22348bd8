#pragma once
// The derived surface photon kernel radius (surface_radius absent or 0):
// from pass 0's surface photons where the camera gathers them and from the
// film's pixels, not from the scene's bounding box (docs/design/photon-beams.md,
// "The surface radius"). Probes: the first smooth surface along camera rays
// through a jittered grid of the film, straight through index-matched
// boundaries (as camera paths go).
//  * density: the distance to the SurfacePhotonsPerGather-th nearest photon
//    on the side the camera sees, the median over the probes;
//  * pixels: PixelFootprints times the probe's pixel footprint (the
//    distance one pixel moves the camera ray on the probe's tangent plane),
//    the median over the probes: the kernel's diameter spans at most four
//    pixels, as the beams' time footprint spans at most four bins
//    (radius_rule.h, TimeBinFraction), so the resolution asked for survives.
// Neither the film's bins nor the surfaces' edges bound it: a photon is
// timed along its own last leg to the gather point (surface_photon_map.h;
// what is left is eta r^2 / (2 leg), second order), and the camera side
// divides by the disc's area on the surface (surface_coverage.h).
#include <cstdint>
#include <vector>

#include <femto/math/vector.h>

#include <transient_beams/surface_photon_map.h>

namespace femto {
class Scene;
}

namespace femto::beams {

/// Where camera paths gather surface photons: the point, the geometric
/// normal on the side the camera sees, and the pixel footprint there.
struct SurfaceProbe {
  Point3f p;
  Normal3f n;
  double footprint = 0.0;
};

/// The first smooth-BSDF hit of the camera ray through one jittered point
/// (a fixed stream) in each of grid x grid cells of the crop window
/// (aperture centre), followed straight through index-matched boundaries.
/// Deterministic.
constexpr int SurfaceProbeGrid = 16;
std::vector<SurfaceProbe> surfaceProbes(const Scene& scene, int grid = SurfaceProbeGrid);

/// Photons per gather the density bound aims at in pass 0 (docs/design/photon-beams.md,
/// "The surface radius": measured on the fog box).
constexpr int SurfacePhotonsPerGather = 64;
/// The pixel bound: the kernel's radius in pixel footprints.
constexpr double PixelFootprints = 2.0;

/// Per probe, the distance to the k-th nearest photon on the probe's side
/// (photon.n toward the probe's normal); `upper` when fewer lie within it.
std::vector<double> nearestPhotonRadii(const std::vector<SurfacePhoton>& photons,
                                       const std::vector<SurfaceProbe>& probes, int k, double upper);

/// The rule's bounds and the radius chosen (the smaller); radius 0 when no
/// probe sees a smooth surface or there are no photons (the caller keeps its
/// default). `upper` caps the density search.
struct DerivedSurfaceRadius {
  double radius = 0.0;
  double density = 0.0;
  double pixels = 0.0;
};
DerivedSurfaceRadius deriveSurfaceRadius(const Scene& scene, const std::vector<SurfacePhoton>& photons, double upper);

}  // namespace femto::beams
