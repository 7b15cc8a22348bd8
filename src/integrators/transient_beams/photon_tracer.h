#pragma once
// The photon pass of transient photon beams (Marco et al. 2017, sec. 4;
// Jarosz et al. 2011, sec. 5): photons leave the emitters (chosen in
// proportion to their power) and carry their optical path length exactly as
// camera paths do -- eta times every segment's length (the medium's index, or
// the dielectric's where there is no medium), plus phase-function scattering
// delays -- so each stores the OPL at which it got where it is.
//
// * Every photon segment inside a medium becomes a Beam reaching to the next
//   surface ("long" beam: the photon itself may scatter earlier, where its
//   next segment starts; the camera side weights a beam by its transmittance),
//   cut short by Russian roulette once that transmittance is low
//   (beam_roulette.h: unbiased, the camera side divides by the survival).
//   BeamStore::Single keeps only the beams of photons that have not scattered
//   yet (straight from the emitter or through mirrors and glass).
//   With VolumeEstimator::Points photons leave photon points instead: a
//   zero-length Beam at every scattering vertex in a medium (ray_point.h),
//   with the direction it arrived from and its power in beam units.
// * Photons reaching a surface with a non-specular BSDF after at least one
//   scattering event or specular bounce become SurfacePhotons: the indirect
//   and caustic light the camera side adds to next-event estimation (which
//   already counts light straight from the emitters).
// * Photons continue through index-matched boundaries, mirrors and glass
//   (volume caustics), bounce off every BSDF (importance transport) and end
//   by Russian roulette, at max_depth, or once their OPL passes the horizon.
// * time_splitting (settings.timeLevels, from pass 1 on): the roulette
//   compares a photon's power with the film's time level at the earliest OPL
//   its light can reach the camera (time_levels.h), and a photon with n >= 2
//   times that level splits at a scattering vertex into n copies of 1/n its
//   power, each sampling its own direction, so late light gets as many
//   beams as early light. Unbiased for any levels.
//
// * stratified_photons: the directions photons leave their emitters in are
//   stratified over a pass (stratifiedDirection: one photon per cell of a
//   k x k grid of the direction sample, jittered; beam photons and the rest
//   apart), so a pass's photons, and its beams, leave the emitters evenly;
//   the pass keeps its expectation, and its variance is at most that of
//   independent photons.
//
// Determinism: photon i of a pass draws its random numbers from its own
// stream, seeded by (pass seed, i), and the pass concatenates per-block
// outputs in photon order, so the maps do not depend on the thread count.
#include <cstdint>
#include <memory>
#include <vector>

#include <femto/math/distribution.h>
#include <transient_beams/beam.h>
#include <transient_beams/beam_settings.h>
#include <transient_beams/camera_reach.h>
#include <transient_beams/surface_photon_map.h>

namespace femto {
class Scene;
class Sampler;
class TileDistribution;
struct MediumSample;
struct SurfaceInteraction;
}  // namespace femto

namespace femto::beams {

/// stratified_photons: the direction sample of photon `index` of a pass
/// whose first `beamPhotons` of `photons` leave beams. Each group (the beam
/// photons, the rest) of n photons puts its first k^2 (k = floor(sqrt(n)))
/// one in each cell of a k x k grid of the unit square, at `jitter` (a
/// uniform point) within it; its last n - k^2 take `jitter` itself. Sums
/// over a group then have at most the variance of independent photons
/// (stratified sampling with proportional allocation) and the same
/// expectation; a photon's position on its emitter and its emitter pick
/// stay independent draws.
Point2f stratifiedDirection(uint64_t index, uint64_t beamPhotons, uint64_t photons, const Point2f& jitter);

/// What one photon pass produced. Powers are per traced photon: estimates
/// divide by photonCount.
struct PhotonPass {
  std::vector<Beam> beams;
  std::vector<SurfacePhoton> surfacePhotons;
  uint64_t photonCount = 0;      // the surface photons' N (photons emitted per pass)
  uint64_t tracedPhotons = 0;    // photons traced: beamPhotonCount when no surface stores photons
  uint64_t beamPhotonCount = 0;  // the first ones, which left the beams: the beams' N
  double traceSeconds = 0.0;     // wall time tracePhotonPass took (statistics)
};

/// Per-thread photon tracer (mutable state: its random stream).
class PhotonTracer {
 public:
  /// `horizon`: OPL past which nothing reaches the film (Infinity: steady).
  PhotonTracer(const Scene& scene, const BeamSettings& settings, double horizon);
  ~PhotonTracer();

  /// Trace photon `index` of the pass seeded `seed`, appending its beams or
  /// photon points (unless `storeBeams` is false) and surface photons.
  void trace(uint64_t seed, uint64_t index, std::vector<Beam>& beams, std::vector<SurfacePhoton>& photons,
             bool storeBeams = true);

 private:
  struct Photon;
  struct Pending;
  /// Follow `photon` from its current ray until it ends.
  void follow(Photon& photon, Sampler& sampler, std::vector<Beam>& beams, std::vector<SurfacePhoton>& photons,
              bool storeBeams);
  // The steps of trace(), in the photon's order; each false ends the photon.
  /// Pick an emitter (by power) and sample the photon's first ray.
  /// Photon `index` of the pass leaves an emitter (its direction
  /// stratified by stratifiedDirection under stratified_photons).
  bool emit(Photon& photon, Sampler& sampler, uint64_t index) const;
  /// The segment through the photon's medium, up to `si` when `hit`: leaves
  /// its beam (when `store`), samples a free flight and weights the power by
  /// it (`arriving`: the power before). Returns the free flight.
  MediumSample crossMedium(Photon& photon, bool hit, const SurfaceInteraction& si, bool store, Sampler& sampler,
                           std::vector<Beam>& beams, Color3f& arriving) const;
  /// A free flight ended in the medium: the photon point (when `store`), the
  /// phase function's delay, time_splitting, the direction on, Russian roulette.
  bool scatterInMedium(Photon& photon, const MediumSample& ms, const Color3f& arriving, bool store, Sampler& sampler,
                       std::vector<Beam>& beams);
  /// The photon reached surface `si`: its clock advances (or starts, from an
  /// emitter at infinity); false past the horizon.
  bool reachSurface(Photon& photon, const SurfaceInteraction& si) const;
  /// A scattering surface: the surface photon (smooth BSDF, indirect light
  /// only), the BSDF's delay, time_splitting, the direction on, Russian roulette.
  bool scatterOnSurface(Photon& photon, const SurfaceInteraction& si, Sampler& sampler,
                        std::vector<SurfacePhoton>& photons);
  /// Sample the direction on from a medium vertex (the photon's vertex, its
  /// ray still the one arriving), then Russian roulette.
  bool leaveMediumVertex(Photon& photon, Sampler& sampler) const;
  /// Sample the direction on from surface `si` (BSDF, importance transport), then Russian roulette.
  bool leaveSurface(Photon& photon, const SurfaceInteraction& si, Sampler& sampler) const;
  /// time_splitting at a scattering vertex, before the direction on is
  /// sampled: n - 1 copies (on `si` when not null, else in the medium) wait
  /// in pending_; the photon keeps 1/n of its power.
  void split(Photon& photon, const SurfaceInteraction* si);
  /// The time level at the photon's vertex (1 without time_splitting).
  float timeLevel(const Photon& photon) const;
  /// Russian roulette past rr_depth segments, on the power relative to the
  /// emitted power and the time level; false ends the photon.
  bool russianRoulette(Photon& photon, Sampler& sampler) const;
  /// The OPL past which light of a photon in a medium of index `eta` can
  /// no longer land in the window anywhere its kernels reach: the horizon
  /// plus (eta + 1) kernel radii (a camera point within r of a beam or
  /// surface photon is up to r nearer the camera, and its light's path up to
  /// eta r shorter); Infinity while the radii are not known (pass 0 derives them).
  double reachLimit(float eta) const;
  /// Whether light at the photon's vertex can still land in the window (CameraReach).
  bool inReach(const Photon& photon) const;

  const Scene& scene_;
  const BeamSettings& settings_;
  double horizon_;
  CameraReach reach_;           // the camera's ray origins, for reachLimit
  double kernelReach_ = 0.0;    // the largest kernel radius of any pass (Infinity: not known yet)
  Distribution1D emitterPower_;
  std::vector<bool> atInfinity_;  // per emitter: directional or environment (photons' clock starts at a surface)
  std::unique_ptr<Sampler> sampler_;
  const TimeLevels* levels_;      // time_splitting's levels, or null
  std::vector<Pending> pending_;  // copies split off, still to be followed
};

/// All photons of one pass (settings.photonCount), traced in parallel.
PhotonPass tracePhotonPass(const Scene& scene, const BeamSettings& settings, uint64_t seed, double horizon);

/// Under mpirun: every rank's traced `beams` and `photons` (its share of the
/// pass's blocks), exchanged and appended to `pass` in rank order. False
/// (and nothing appended) when some rank holds a beam in a medium the scene's
/// list does not name: then every rank traces every block itself.
bool exchangePhotons(const Scene& scene, TileDistribution& job, const std::vector<Beam>& beams,
                     const std::vector<SurfacePhoton>& photons, PhotonPass& pass);

}  // namespace femto::beams
