#pragma once
// The parameters of the transient_beams integrator (see the table in
// transient_beams.cpp), read and checked once; immutable afterwards. Errors
// name the scene file and line of the offending parameter.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <femto/base/error.h>
#include <femto/core/properties.h>
#include <femto/math/bbox.h>
#include <femto/render/path_depth.h>
#include <transient_beams/beam.h>

namespace femto::beams {

/// Which photon segments in media become beams.
enum class BeamStore {
  Single,  // only photons that have not scattered yet (straight from the emitter, through specular chains): single scattering
  All,     // every segment: all orders of scattering in media
};

/// What photons leave in media, and so which estimate a camera segment in a
/// medium makes (docs/photon-beams.md, "Photon points vs photon beams").
enum class VolumeEstimator {
  /// Photon beams and the ray x beam 1D estimate (ray_beam.h): the default.
  Beams,
  /// Photon points at the photons' scattering vertices and the beam radiance
  /// estimate, "point x beam 2D" (ray_point.h): for comparison.
  Points,
};

/// max_depth (the longest camera + photon path in segments, -1: no limit),
/// rr_depth (photon segments before Russian roulette may end a photon) and
/// depthAllowed() come from PathDepthSettings, read with path's rule.
struct BeamSettings : PathDepthSettings {
  int passes = 1;
  int64_t photonCount = 100000;  // photons traced per pass (all leave surface photons)
  int64_t beamPhotonCount = 10000;  // how many of them (the first ones) leave beams; 0: all
  float radius = 0.0f;           // beam kernel radius of pass 0 (0: derived from the scene size)
  float surfaceRadius = 0.0f;    // surface photon kernel radius of pass 0 (0: derived)
  float gatherFraction = 1.0f;   // probability that a camera segment in a medium gathers beams (weight 1/it)
  float alpha = 0.7f;            // progressive radius reduction, in (0, 1]
  BeamStore store = BeamStore::All;
  VolumeEstimator volumeEstimator = VolumeEstimator::Beams;
  bool observerTime = true;      // the camera segment counts toward the OPL
  bool hideEmitters = false;     // emitters seen directly appear black
  SourceLocation location;       // the <integrator> element, for errors found at render time

  /// Read and validate every parameter (unknown ones are the loader's business).
  static BeamSettings parse(const Properties& props);

  /// Fill in the surface radius if not given, as a fraction of the scene's
  /// bounding-box diagonal; an error naming the integrator when the scene has
  /// no extent. The beam radius, if not given, stays 0 until
  /// withBeamRadiusFrom() sees the first pass's beams.
  BeamSettings resolved(const BoundingBox3f& sceneBounds) const;

  /// If no beam radius is given, derive the first pass's from its beams
  /// (total length L, bounding box volume V): a camera segment of length
  /// V^(1/3) through beams spread evenly and isotropically over V passes
  /// within r of about L V^(1/3) 2r (pi/4) / V of them (the mean |sin| of
  /// isotropic directions is pi/4), so
  ///   r = 2 TargetPairHits V^(2/3) / (pi L)
  /// gives each such segment about TargetPairHits pairs: the estimate's
  /// cost per camera segment stays bounded whatever the photon count, and
  /// the radius shrinks as photons are added. Photon points (P of them,
  /// zero-length beams) instead meet a segment in its cylinder of volume
  /// pi r^2 V^(1/3), P pi r^2 V^(1/3) / V of them, so
  ///   r = sqrt(TargetPairHits V^(2/3) / (pi P)).
  /// Falls back to a fraction of `sceneBounds`' diagonal when the beams span
  /// no volume. Deterministic: the beams are the same for a given seed on any
  /// thread count.
  BeamSettings withBeamRadiusFrom(const std::vector<Beam>& beams, const BoundingBox3f& sceneBounds) const;

  /// Pairs per camera segment the derived beam radius aims at: enough that
  /// a gather is worth its query (a camera segment's BVH traversal costs
  /// about as much as tens of pair estimates), few enough that the kernel
  /// stays narrow (docs/BENCHMARKS.md, "transient_beams cost").
  static constexpr double TargetPairHits = 25.0;

  /// Kernel radii of pass `pass` (0-based). The beam estimate uses a 1D
  /// kernel, whose variance grows as 1/r: r_{i+1} = r_i (i + alpha) / (i + 1)
  /// (Jarosz, Nowrouzezahrai, Thomas, Sloan, Zwicker 2011, "Progressive Photon
  /// Beams", sec. 4). The surface estimate uses a 2D kernel (variance ~ 1/r^2):
  /// r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) (Knaus and Zwicker 2011,
  /// "Progressive Photon Mapping: A Probabilistic Approach", eq. 20). Photon
  /// points in media are gathered with a 2D kernel too (the disc across the
  /// camera ray, ray_point.h), so their radius follows the surface schedule.
  /// beamRadius() is the medium kernel's radius, for beams or points.
  float beamRadius(int pass) const;
  float surfaceRadiusOf(int pass) const;

  /// Photons per pass that leave beams (the estimate's N for beams).
  int64_t beamPhotons() const { return beamPhotonCount > 0 ? std::min(beamPhotonCount, photonCount) : photonCount; }
};

}  // namespace femto::beams
