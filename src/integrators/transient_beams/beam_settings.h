#pragma once
// The parameters of the transient_beams integrator (see the table in
// transient_beams.cpp), read and checked once; immutable afterwards. Errors
// name the scene file and line of the offending parameter.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <femto/base/error.h>
#include <femto/core/properties.h>
#include <femto/math/bbox.h>
#include <femto/math/constants.h>
#include <femto/render/path_depth.h>
#include <femto/time/time_levels.h>
#include <transient_beams/beam.h>
#include <transient_beams/beam_roulette.h>
#include <transient_beams/radius_rule.h>

namespace femto::beams {

struct SceneCoverage;  // boundary_coverage.h

/// Which photon segments in media become beams.
enum class BeamStore {
  Single,  // only photons that have not scattered yet (straight from the emitter, through specular chains): single
           // scattering
  All,     // every segment: all orders of scattering in media
};

/// What photons leave in media, and so which estimate a camera segment in a
/// medium makes (docs/design/photon-beams.md, "Photon points vs photon beams").
enum class VolumeEstimator {
  /// Photon beams and the ray x beam 1D estimate (ray_beam.h): the default.
  Beams,
  /// Photon points at the photons' scattering vertices and the beam radiance
  /// estimate, "point x beam 2D" (ray_point.h): for comparison.
  Points,
};

/// The derived beam radius and the four bounds it is the smallest of
/// (+Infinity: no bound; BeamSettings::withBeamRadiusFrom).
struct DerivedRadius {
  double density = 0.0, time = 0.0, boundary = 0.0, light = Infinity, radius = 0.0;
};

/// Surface gathers per pixel and pass the derived surface gather fraction aims at.
inline constexpr double SurfaceGathersPerPixel = 2.0;
/// The derived surface gather fraction's floor.
inline constexpr double MinSurfaceGatherFraction = 0.125;

/// The beam gather fraction's rule (issue 33: a cost-aware gather). A gather
/// (one camera segment's beam query) costs G and the rest of a camera
/// sample S, the photon pass and the maps' build shared over the pass's
/// samples included; made with probability q it adds roulette variance
/// about (1/q - 1) times what the sample already has, so relMSE x CPU,
/// (S + q G)(1/q), is least at q = sqrt(S / G). The costs are counts (from
/// pass 0's pilot, the same on every rank and thread count) weighed by
/// fixed per-operation times measured on the fog box and ToF-Tungsten's
/// port (docs/design/photon-beams.md, "A cost-aware gather fraction").
struct GatherCosts {
  double gathersPerSample = 0.0;         // camera segments in media per camera sample
  double boxes = 0.0, candidates = 0.0;  // per gather: map piece boxes crossed, beams tested
  double pairs = 0.0;                    // per gather: pairs that deposit
  double surfaceQueries = 0.0, surfacePhotons = 0.0;  // per camera sample
  double photonsPerSample = 0.0, piecesPerSample = 0.0, storedPerSample = 0.0;  // the pass's, shared
  double samplesPerPixel = 1.0;  // camera samples per pixel and pass
  /// sqrt(S / (RouletteVarianceShare G)) within [max(MinGatherFraction,
  /// 1 / samplesPerPixel), 1]: at least one gather a pixel per pass (the
  /// strata make it exact; with fewer, a pixel's pass holds no beams); 1
  /// without gathers.
  double fraction() const;
};
/// The derived beam gather fraction's floor.
inline constexpr double MinGatherFraction = 1.0 / 16.0;
/// How much more of a sample's variance a skipped gather would have added
/// than the roulette does: a pass's gathers in one pixel meet the same
/// beams, so skipping some loses less than an independent estimate. Fitted:
/// sqrt(S / G) read 2.7-5x the best q measured on the fog box (256 and 1024
/// bins) and the thick medium (docs/design/photon-beams.md).
inline constexpr double RouletteVarianceShare = 8.0;

/// max_depth (the longest camera + photon path in segments, -1: no limit),
/// rr_depth (photon segments before Russian roulette may end a photon) and
/// depthAllowed() come from PathDepthSettings, read with path's rule.
struct BeamSettings : PathDepthSettings {
  int passes = 1;
  int64_t photonCount = 100000;       // photons traced per pass (all leave surface photons)
  int64_t beamPhotonCount = 10000;    // how many of them (the first ones) leave beams; 0: all
  bool beamPhotonCountGiven = false;  // by the scene: withBeamsForRadius() then keeps it
  float radius = 0.0f;                // beam kernel radius of pass 0 (0: derived, withBeamRadiusFrom)
  float surfaceRadius = 0.0f;         // surface photon kernel radius of pass 0 (0: derived)
  bool surfaceRadiusFinal = false;    // given, or derived from pass 0 (not the scene's default it starts from)
  /// Width (OPL) of the surface photons' causal time kernel in pass 0: a
  /// photon arriving at a gather point at OPL t deposits uniformly over
  /// [t, t + w] (docs/design/photon-beams.md, "The surface time kernel").
  /// Negative (absent): derived, withSurfaceTimeWidthFor(); 0: at the instant t.
  float surfaceTimeWidth = -1.0f;
  /// Probability that a camera segment in a medium gathers beams (weight
  /// 1/it). Negative (absent): 1 in pass 0, then derived from pass 0's
  /// pilot (GatherCosts::fraction); gathers() reads it.
  float gatherFraction = -1.0f;
  /// Probability that a camera sample's surface vertex gathers surface
  /// photons (weight 1/it). Negative (absent): derived, withSurfaceGatherFor().
  float surfaceGatherFraction = -1.0f;
  float gatherRoulette = BeamRoulette::GatherTau;  // T_cam where a gather's Russian roulette starts (0: never)
  float alpha = 0.9f;  // progressive radius reduction, in (0, 1] (docs/design/photon-beams.md: why 0.9)
  BeamStore store = BeamStore::All;
  VolumeEstimator volumeEstimator = VolumeEstimator::Beams;
  bool observerTime = true;   // the camera segment counts toward the OPL
  bool hideEmitters = false;  // emitters seen directly appear black
  /// time_splitting: photons are rouletted and split against the film's time
  /// profile (time_levels.h) from pass 1 on, read by a pilot of pass 0's
  /// camera samples (transient_beams.cpp); `timeLevels` holds it then.
  bool timeSplitting = true;
  /// The directions photons leave the emitters in are stratified over a
  /// pass (photon_tracer.h, stratifiedDirection) rather than independent.
  bool stratifiedPhotons = true;
  /// time_gating: the camera side skips what lands wholly before the film's
  /// window but a before_window_rate share of it, weighted by its inverse
  /// (camera_tracer.h, WindowGate; the map skips such beam pieces).
  bool timeGating = true;
  float beforeWindowRate = 0.125f;
  std::shared_ptr<const TimeLevels> timeLevels;
  SourceLocation location;    // the <integrator> element, for errors found at render time

  /// Read and validate every parameter (unknown ones are the loader's business).
  static BeamSettings parse(const Properties& props);

  /// Fill in the surface radius if not given, as a fraction of the scene's
  /// bounding-box diagonal (a scene without shapes has no surfaces to gather
  /// on: any radius); an error naming the integrator when the scene's extent
  /// is not finite. Pass 0 then derives it from its photons and the film
  /// (surface_radius_rule.h), within 4 times this; this stays where no probe
  /// sees a smooth surface. The beam radius, if not given, stays 0 until
  /// withBeamRadiusFrom() sees the first pass's beams.
  BeamSettings resolved(const BoundingBox3f& sceneBounds) const;

  /// If no beam radius is given, derive the first pass's (radius_rule.h,
  /// docs/design/photon-beams.md, "Derived beam radius"): the smallest of
  ///  * the density radius: probe segments (camera rays through the film in
  ///    media, radius_probe.h) meet TargetPairHits of `beams` on average,
  ///    so a gather's cost stays bounded whatever the photon count;
  ///  * the time radius: a pair's OPL footprint stays within TimeBinFraction
  ///    bins of `grid` (none for steady films);
  ///  * the boundary radius: the kernel's loss where beams end stays below
  ///    BoundaryBiasTarget of a camera segment's estimate (the planar
  ///    model, boundaryRadius, and for beams with `coverage` given also the
  ///    loss counted on the scene, coveredBoundaryRadius in
  ///    boundary_coverage.h);
  ///  * the light radius `lightBound` (light_leak.h): the kernel's leak of a
  ///    point light's singular density across the view's edge or its
  ///    medium's boundary stays below LightBiasTarget.
  /// Without probes (no medium seen straight from the camera) the density
  /// radius falls back to the beams' spread (total length L in a bounding
  /// box of volume V: r = 2 H V^(2/3) / (pi L), photon points
  /// r = sqrt(H V^(2/3) / (pi P)); at most 1 % of the scene's diagonal).
  /// Deterministic: the beams are the same for a given seed on any thread
  /// count, the probes fixed. `chosen`, if given, receives the four radii.
  /// `sizedFor`: the derivation these beams were traced for
  /// (withBeamsForRadius gave more beams for its radius): its density and
  /// oblique time bounds are kept (the latter derived again only if the
  /// boundary now allows more than its cap) and the boundary loss is
  /// counted again, on as many more pairs.
  BeamSettings withBeamRadiusFrom(const std::vector<Beam>& beams, const std::vector<ProbeSegment>& probes,
                                  const TimeGrid& grid, const BoundingBox3f& sceneBounds,
                                  DerivedRadius* chosen = nullptr, double lightBound = Infinity,
                                  const SceneCoverage* coverage = nullptr,
                                  const DerivedRadius* sizedFor = nullptr) const;

  /// When the derived radius is below the density radius (the time or
  /// boundary bound decided) and the scene did not give beam_photon_count:
  /// as many more beam photons as keep TargetPairHits pairs per camera
  /// segment at that radius (pairs grow as N r for beams, N r^2 for points),
  /// at most all photons. Unchanged otherwise.
  BeamSettings withBeamsForRadius(const DerivedRadius& derived) const;

  /// Pairs per camera segment the density radius aims at, from the balance
  /// of a segment's error per unit cost (docs/design/photon-beams.md, "Derived beam
  /// radius"): the beams' part of the variance falls as 1/h (h pairs), the
  /// camera side's (pixel footprint, surfaces) does not depend on h; a query
  /// costs C0 + c h with C0 (traversal, the rest of the camera sample) about
  /// 30 pairs' worth; the kernel bias grows as r^2 ~ h^2. So h well above
  /// C0 / c, until the beams' variance is below the camera side's: measured
  /// by radius sweeps (tools/bench/beams_radius_sweep.py) at 150-350 pairs on
  /// the large medium and the ToF-Tungsten port (the box and the fog box are
  /// bound by the boundary radius first). 25 (the earlier rule) lost 2-5x.
  static constexpr double TargetPairHits = 300.0;

  /// The surface time kernel's width when none is given (the surface radius
  /// known): the smaller of TimeBinFraction bins of `grid` (radius_rule.h),
  /// the footprint the beams' pairs are held to, so that surfaces and media
  /// keep the film's time resolution alike, and 2 surfaceRadius, the OPL
  /// light takes to cross the kernel's disc, so that the space-time kernel
  /// is no longer in time than in space; 0 when that is under a bin (a
  /// kernel within one bin lowers no bin's variance, and only shifts
  /// light later) and for steady films (no time axis). Unchanged when given.
  BeamSettings withSurfaceTimeWidthFor(const TimeGrid& grid) const;
  /// The surface gather fraction, unless given, for `spp` camera samples
  /// per pixel and pass: SurfaceGathersPerPixel gathers a pixel (within
  /// [MinSurfaceGatherFraction, 1]). A pass's photons are shared by all of
  /// a pixel's samples, so beyond a few gathers more of them lower only the
  /// part of the noise from where in the pixel they land, at the cost of a
  /// photon query each (docs/design/photon-beams.md, "Surface gathers").
  BeamSettings withSurfaceGatherFor(uint32_t spp) const;
  /// The beam gather fraction in use: gatherFraction, 1 while it is still to be derived.
  float gathers() const { return gatherFraction > 0.0f ? gatherFraction : 1.0f; }

  /// Kernel radii of pass `pass` (0-based). The beam estimate uses a 1D
  /// kernel, whose variance grows as 1/r: r_{i+1} = r_i (i + alpha) / (i + 1)
  /// (Jarosz, Nowrouzezahrai, Thomas, Sloan, Zwicker 2011, "Progressive Photon
  /// Beams", sec. 4). The surface estimate uses a 2D kernel (variance ~ 1/r^2):
  /// r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1) (Knaus and Zwicker 2011,
  /// "Progressive Photon Mapping: A Probabilistic Approach", eq. 20). Photon
  /// points in media are gathered with a 2D kernel too (the disc across the
  /// camera ray, ray_point.h), so their radius follows the surface schedule.
  /// beamRadius() is the medium kernel's radius, for beams or points.
  /// With a surface time kernel (width w > 0) the surface kernel is 3D, its
  /// variance ~ 1 / (r^2 w) and its bias ~ a r^2 + b w (the causal kernel
  /// shifts a profile by w / 2: first order): the volume r^2 w shrinks by
  /// the same factor, split evenly, r^2 and w each by its square root
  /// (balancing the two biases' rates minimises the asymptotic MSE;
  /// docs/design/photon-beams.md, "The surface time kernel").
  float beamRadius(int pass) const;
  float surfaceRadiusOf(int pass) const;
  float surfaceTimeWidthOf(int pass) const;

  /// Photons per pass that leave beams (the estimate's N for beams).
  int64_t beamPhotons() const { return beamPhotonCount > 0 ? std::min(beamPhotonCount, photonCount) : photonCount; }
};

}  // namespace femto::beams
