#include <transient_beams/camera_tracer.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>
#include <femto/render/bsdf.h>
#include <femto/render/medium.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/transient_integrator.h>
#include <femto/transport/direct_lighting.h>
#include <femto/transport/optical_path.h>
#include <femto/transport/transient_emission.h>
#include <femto/transport/volumetric.h>
#include <transient_beams/beam_roulette.h>
#include <transient_beams/boundary_extension.h>
#include <transient_beams/medium_extent.h>
#include <transient_beams/ray_beam.h>
#include <transient_beams/ray_point.h>
#include <transient_beams/surface_coverage.h>

namespace femto::beams {
namespace {

/// Specular bounces before a camera path is abandoned (max_depth may be unlimited).
constexpr int MaxSpecularBounces = 64;
/// Photons arriving this close to grazing (|cos| w.r.t. the shading normal)
/// are skipped: f = eval / |cos| would divide by rounding noise.
constexpr float MinPhotonCosine = 1e-4f;
/// Chords a ray x beam pair's deposit is cut into at most (PairOpl::pieces).
constexpr int MaxPairPieces = 32;
/// Salts of the camera sample's strata (Sampler::stratum) that decide its
/// beam gathers and its surface photon gathers.
constexpr uint64_t BeamGatherSalt = 0x6265616d73ull, SurfaceGatherSalt = 0x73757266ull;

/// Russian roulette on a whole gather made with probability q (absent, <= 0,
/// or 1: always): the weight of its estimates, 1/q, or 0 when it is skipped.
/// The sample's stratum decides, so q of a pixel's samples gather, not a
/// binomial number; q = 1 draws nothing.
double gatherWeight(Sampler& sampler, uint64_t salt, float q) {
  if (!(q > 0.0f && q < 1.0f)) return 1.0;
  return sampler.stratum(salt) < q ? 1.0 / double(q) : 0.0;
}

}  // namespace

/// The mutable state of one camera path: where it is and its OPL there
/// (OpticalPath), and what it carries.
struct CameraTracer::Path : OpticalPath {
  bool cameraSegment = true;  // no (specular) scattering vertex yet
  Color3f throughput{1.0f};
  int segments = 0;    // camera segments completed before the current one
  ScatterOrigin prev;  // camera rays and specular bounces (delta): emission found by a ray counts fully
};

void CameraTracer::sample(const Scene& scene, const Ray& cameraRay, Sampler& sampler, RadianceRecorder& recorder) {
  ++stats_.cameraRays;
  if (settings_.maxDepth == 0) return;
  const double horizon = recorder.horizon();
  Path s;
  s.ray = Ray(cameraRay.o, cameraRay.d);
  s.medium = scene.sensor().medium();
  s.vertex = cameraRay.o;
  for (int passThrough = 0, bounces = 0; passThrough < MaxPassThrough && bounces < MaxSpecularBounces;) {
    SurfaceInteraction si;
    bool hit = scene.rayIntersect(s.ray, si);
    if (s.medium && !crossMedium(scene, s, hit, si, sampler, recorder)) return;
    if (!hit) {
      recordEnvironment(scene, s, recorder);
      return;
    }
    if (!s.advance(si.p, segmentCounts(settings_.observerTime, s.cameraSegment)) || s.opl >= horizon) return;
    recordEmission(scene, s, si, recorder);
    if (isPassThrough(si)) {
      s.crossBoundary(si);
      ++passThrough;
      continue;
    }
    if (!scatterOnSurface(scene, s, si, sampler, recorder)) return;
    passThrough = 0;
    ++bounces;
  }
}

bool CameraTracer::crossMedium(const Scene& scene, Path& s, bool hit, const SurfaceInteraction& si, Sampler& sampler,
                               RadianceRecorder& recorder) {
  // An unbounded segment ends where its OPL passes the horizon, unless it
  // adds no OPL (observer time off): then light scattered far along it still
  // arrives in time, and only the transmittance bounds it.
  const bool counted = segmentCounts(settings_.observerTime, s.cameraSegment);
  float tMax = hit ? distance(s.vertex, si.p)
                   : unboundedSegmentLength(*s.medium, s.opl, counted ? recorder.horizon() : Infinity);
  if (tMax > 0.0f && std::isfinite(tMax)) {
    // To the exact surface point the segment ends on: the ray that found it
    // left from an offset origin, so s.ray.d from the vertex passes beside
    // it (by the offset, ~1e-4 of the scene) and could end outside the
    // medium, where light arrives earlier than anywhere inside (random media
    // seed 23: a trace of energy before the earliest arrival).
    const Vec3f direction = hit ? (si.p - s.vertex) / tMax : s.ray.d;
    gatherBeams(scene, s, direction, tMax, sampler, recorder);
  }
  if (!hit) return false;  // escaping through a medium: attenuated to nothing
  s.throughput *= s.medium->transmittance(s.ray, tMax, sampler);
  return !s.throughput.isBlack();
}

bool CameraTracer::emissionCounts(const Path& s) const {
  return !(settings_.hideEmitters && s.segments == 0) && settings_.depthAllowed(s.segments + 1);
}

void CameraTracer::recordEnvironment(const Scene& scene, const Path& s, RadianceRecorder& recorder) const {
  if (emissionCounts(s)) recordEnvironmentEmission(scene, s.ray, s.prev, s.opl, s.throughput, recorder);
}

void CameraTracer::recordEmission(const Scene& scene, const Path& s, const SurfaceInteraction& si,
                                  RadianceRecorder& recorder) const {
  if (!si.emitter() || !emissionCounts(s)) return;
  // prev.delta: the distance is unused.
  recordSurfaceEmission(scene, si, s.ray.d, si.t, s.prev, s.opl, s.throughput, recorder);
}

bool CameraTracer::scatterOnSurface(const Scene& scene, Path& s, const SurfaceInteraction& si, Sampler& sampler,
                                    RadianceRecorder& recorder) {
  ++s.segments;
  const BSDF& bsdf = *si.bsdf();
  if (bsdf.hasDelay()) {  // scattering here takes time: it delays NEE, surface photons and specular paths alike
    s.opl += bsdf.sampleDelay(sampler.next1D());
    if (s.opl >= recorder.horizon()) return false;
  }
  if (bsdf.hasSmooth()) {
    nextEvent(scene, s, si, sampler, recorder);
    gatherSurfacePhotons(scene, s, si, sampler, recorder);
    if (!(bsdf.flags() & BSDFFlags::Delta)) return false;
  }
  return followSpecular(s, si, sampler);
}

bool CameraTracer::followSpecular(Path& s, const SurfaceInteraction& si, Sampler& sampler) const {
  // The specular components (mirror, glass, a coating's reflection): a sample
  // that picks a smooth component ends the path, which the estimates at this
  // vertex already covered.
  BSDFSample bs;
  Color3f weight = si.bsdf()->sample(si, sampler.next1D(), sampler.next2D(), bs);
  if (!(bs.pdf > 0.0f) || weight.isBlack() || !(bs.sampledFlags & BSDFFlags::Delta)) return false;
  if (!settings_.depthAllowed(s.segments + 1)) return false;
  Vec3f wo = si.toWorld(bs.wo);
  s.throughput *= weight;
  s.leaveSurface(si, wo, bs.eta);
  s.cameraSegment = false;
  return true;
}

void CameraTracer::gatherBeams(const Scene& scene, const Path& s, const Vec3f& direction, float tMax, Sampler& sampler,
                               RadianceRecorder& recorder) {
  // Russian roulette on the whole gather (docs/design/photon-beams.md, "Gather
  // fraction"): the expectation is unchanged.
  const double gathered = gatherWeight(sampler, BeamGatherSalt, settings_.gathers());
  if (gathered == 0.0) return;
  const Medium& medium = *s.medium;
  // Russian roulette along the segment (beam_roulette.h, "Along a camera
  // segment"): past where T_cam falls to gather_roulette the query reaches a
  // random length and its pairs weigh 1 / S(tRay). Only drawn when the
  // segment reaches that far, so thin media render exactly as without it.
  const BeamRoulette roulette = BeamRoulette::of(medium, settings_.gatherRoulette);
  // ...and the beams here were ended by the beams' roulette of this medium.
  const BeamRoulette beamRoulette = BeamRoulette::of(medium);
  CameraSegment segment;
  segment.ray = Ray(s.vertex, direction);  // from the exact vertex, where the path's OPL is s.opl
  segment.tMax = tMax > roulette.start() ? std::min(tMax, roulette.sampleLength(sampler.next1D())) : tMax;
  // Observer time off: the camera's first segment adds no OPL (its beams
  // then show where light is, not when the camera sees it).
  segment.eta = segmentCounts(settings_.observerTime, s.cameraSegment) ? medium.eta() : 0.0f;
  // Beams (ray x beam 1D) or photon points (zero-length beams, the beam
  // radiance estimate, ray_point.h): the same estimate once the pair's
  // geometry is known, T_beam aside (a point's power already holds it).
  const bool points = settings_.volumeEstimator == VolumeEstimator::Points;
  const std::vector<Beam>& beams = maps_.beams.beams();
  const PhaseFunction& phase = medium.phase();
  // Time gating: beams (not photon points) without scattering delays.
  const WindowGate gate =
      points || phase.hasDelay() ? WindowGate() : windowGate(scene, recorder, sampler);
  // The map skips pieces whose pairs all land before the window (beam_map.h).
  const double minOpl = gate.dropBefore ? gate.windowStart - gate.late - s.opl - double(segment.eta) * segment.tMax
                                        : -Infinity;
  // Beams: the map also drops those whose axis the segment's line passes
  // beyond the radius (beam_map.h, Cull::Lines).
  stats_.piecesCrossed += maps_.beams.queryUnsorted(segment, scratch_, marks_,
                                                    points ? BeamMap::Cull::Boxes : BeamMap::Cull::Lines, minOpl);
  ++stats_.segments;
  stats_.candidates += scratch_.size();
  const double horizon = recorder.horizon();
  const double pieceTolerance = recorder.timeGrid().bins > 0 ? 0.125 * recorder.timeGrid().binWidth : 0.0;
  const double invPhotons = 1.0 / double(maps_.beamPhotonCount);
  for (uint32_t index : scratch_) {
    const Beam& beam = beams[index];
    // Beams of another medium overlapping this one (nested media) do not scatter here.
    if (beam.medium != &medium || !settings_.depthAllowed(s.segments + 1 + beam.depth)) continue;
    const double opl0 = s.opl + beam.opl;
    if (!(opl0 < horizon)) continue;
    RayBeamHit hit;
    const bool near = points ? rayPointIntersect(segment, beam, maps_.beamRadius, hit)
                             : rayBeamIntersect(segment, beam, maps_.beamRadius, hit);
    if (!near || !(hit.kernel > 0.0f)) continue;
    // Wholly before the window: skipped, or weighted (one draw per gather).
    const bool before = gate.before(opl0 + hit.oplEnd);
    if (before && gate.dropBefore) continue;
    const Point3f x = segment.ray(hit.tRay);
    float fp = phase.eval(-s.ray.d, -beam.direction);
    if (!(fp > 0.0f)) continue;
    Color3f value = s.throughput * medium.scatteringCoefficient(x) * fp * beam.power *
                    float(double(hit.kernel) * invPhotons * gathered * (before ? gate.beforeWeight : 1.0));
    if (value.isBlack()) continue;
    value *= medium.transmittance(segment.ray, hit.tRay, sampler) * roulette.inverseSurvival(hit.tRay);
    if (!points) {
      value *= medium.transmittance(Ray(beam.origin, beam.direction), hit.tBeam, sampler) *
               beamRoulette.inverseSurvival(hit.tBeam);
      // On an extension (boundary_extension.h) the density continues. The
      // point's parameter against its own clamp: exactly 0 on the beam
      // (hit.tBeam, computed another way, differs by rounding there), so
      // only pairs on an extension pay the exponentials.
      if (beam.before > 0.0f || beam.after > 0.0f) {
        const float along = dot(x - beam.origin, beam.direction);
        value *= extensionContinuation(medium, along - std::clamp(along, 0.0f, beam.length));
      }
    }
    if (value.isBlack()) continue;
    double delay = phase.hasDelay() ? phase.sampleDelay(sampler.next1D()) : 0.0;
    const EmissionPulse& pulse = scene.emitters()[beam.emitter]->pulse();
    // The pair's arrival density: uniform over [oplBegin, oplEnd] unless the
    // OPL bends within the overlap by more than an eighth of a bin (a
    // stationary point without observer time, the beam's start nearby):
    // then chords of it (ray_beam.h, PairOpl::pieces).
    PairOpl::Piece pieces[MaxPairPieces];
    const int count = points || !(pieceTolerance > 0.0)
                          ? 1
                          : PairOpl(segment, beam, maps_.beamRadius, hit).pieces(pieceTolerance, pieces, MaxPairPieces);
    if (count <= 1)
      recorder.addPulsed(opl0 + hit.oplBegin + delay, opl0 + hit.oplEnd + delay, value, pulse);
    else
      for (int i = 0; i < count; ++i)
        recorder.addPulsed(opl0 + pieces[i].begin + delay, opl0 + pieces[i].end + delay,
                           value * float(pieces[i].weight), pulse);
    ++stats_.pairHits;
  }
}

void CameraTracer::nextEvent(const Scene& scene, const Path& s, const SurfaceInteraction& si, Sampler& sampler,
                             RadianceRecorder& recorder) {
  if (!settings_.depthAllowed(s.segments + 1)) return;
  DirectionSample ds;
  Color3f emitterWeight = scene.sampleEmitterDirection(si, sampler.next2D(), ds, false);
  if (!(ds.pdf > 0.0f) || emitterWeight.isBlack()) return;
  // The light segment's OPL is at least its length (eta >= 1).
  if (std::isfinite(ds.dist) && s.opl + ds.dist >= recorder.horizon()) return;
  // Time gating: light that lands wholly before the window (its OPL is at
  // most the largest index times the straight distance) is made for
  // before_window_rate of the connections, weighted by its inverse.
  double weight = 1.0;
  if (std::isfinite(ds.dist)) {
    const WindowGate gate = windowGate(scene, recorder, sampler);
    if (gate.before(s.opl + double(scene.largestMediumEta()) * double(ds.dist))) {
      if (gate.dropBefore) return;
      weight = gate.beforeWeight;
    }
  }
  // The camera path never samples the BSDF at this vertex (photons cover
  // indirect light), so emitter sampling is the only strategy: weight 1.
  Color3f f = si.bsdf()->eval(si, si.toLocal(ds.d));
  if (f.isBlack()) return;
  Connection c = connect(scene, si, ds.d, ds.p, ds.dist, mediumAfter(si, ds.d, s.medium), s.surfaceEta, sampler);
  if (c.transmittance.isBlack()) return;
  recorder.addPulsed(s.opl + c.opl, s.opl + c.opl, s.throughput * f * emitterWeight * c.transmittance * float(weight),
                     ds.emitter->pulse());
}

CameraTracer::WindowGate CameraTracer::windowGate(const Scene& scene, RadianceRecorder& recorder,
                                                 Sampler& sampler) const {
  WindowGate gate;
  const TimeGrid& grid = recorder.timeGrid();
  const double horizon = recorder.horizon();
  if (!settings_.timeGating || grid.bins <= 0 || !std::isfinite(grid.start) || !std::isfinite(horizon) ||
      !(settings_.beforeWindowRate < 1.0f))
    return gate;
  // The horizon is the window's end plus the time filter's reach.
  if (std::isnan(latestPulse_)) {  // once per camera sample, not per gather
    latestPulse_ = 0.0;
    for (const auto& emitter : scene.emitters()) latestPulse_ = std::max(latestPulse_, emitter->pulse().latest());
  }
  const double latest = latestPulse_;
  if (!std::isfinite(latest)) return gate;  // a continuous pulse: everything reaches the window
  gate.active = true;
  gate.windowStart = grid.start;
  gate.late = latest + (horizon - grid.end());
  const float rate = settings_.beforeWindowRate;
  if (rate > 0.0f && sampler.next1D() < rate)
    gate.beforeWeight = 1.0 / double(rate);
  else
    gate.dropBefore = true;
  return gate;
}

void CameraTracer::gatherSurfacePhotons(const Scene& scene, const Path& s, const SurfaceInteraction& si,
                                        Sampler& sampler, RadianceRecorder& recorder) {
  // Russian roulette on the gather, as for beams (surface_gather_fraction).
  const double gathered = gatherWeight(sampler, SurfaceGatherSalt, settings_.surfaceGatherFraction);
  if (gathered == 0.0) return;
  const float r = maps_.surfaceRadius;
  // Time gating: this gather skips (the map does) the photons whose light
  // lands wholly before the window, or weighs them (WindowGate).
  const WindowGate gate = windowGate(scene, recorder, sampler);
  maps_.photons.query(si.p, r, scratch_,
                      gate.dropBefore ? gate.windowStart - gate.late - maps_.surfaceTimeWidth - s.opl : -Infinity);
  ++stats_.surfaceQueries;
  stats_.surfacePhotons += scratch_.size();
  if (scratch_.empty()) return;
  const BSDF& bsdf = *si.bsdf();
  // Only photons that arrived on the side the camera sees.
  const Vec3f toCamera = si.toWorld(si.wi);
  const Normal3f side = dot(si.n, toCamera) >= 0.0f ? si.n : -si.n;
  // Over the disc's area on this surface (surface_coverage.h: past an edge
  // it holds no photons), counted once a photon contributes.
  double norm = 0.0;
  const double horizon = recorder.horizon();
  // The photons found are scattered over the map's array (72 bytes each, a
  // pass holds 10^5-10^6): fetched a few ahead, as the beams' line test does
  // (beam_map.cpp), the reads overlap.
  constexpr size_t Ahead = 8;
  const SurfacePhoton* photons = maps_.photons.photons().data();
  for (size_t i = 0; i < scratch_.size(); ++i) {
    if (i + Ahead < scratch_.size()) __builtin_prefetch(&photons[scratch_[i + Ahead]]);
    const SurfacePhoton& photon = photons[scratch_[i]];
    if (dot(photon.n, side) <= 0.0f || !settings_.depthAllowed(s.segments + photon.depth)) continue;
    // Timed along the photon's last leg to this point (surface_photon_map.h).
    const double opl = s.opl + photon.opl + lastLegDelay(photon, si.p);
    if (!(opl < horizon)) continue;
    // Wholly before the window: skipped, or weighted (one draw per gather).
    const bool before = gate.before(opl + maps_.surfaceTimeWidth);
    if (before && gate.dropBefore) continue;
    Vec3f local = si.toLocal(photon.wi);
    float cosine = std::abs(local.z);
    if (cosine < MinPhotonCosine) continue;
    // eval() includes |cos wo|: divide it out to get f (Jensen's estimate uses f alone).
    Color3f f = bsdf.eval(si, local, TransportMode::Radiance) / cosine;
    if (f.isBlack()) continue;
    if (norm == 0.0)
      norm = gathered / (double(Pi) * double(r) * double(r) * double(maps_.photonCount) *
                             std::max(coveredShare(scene, si.p, Vec3f(side), double(r)), MinCoveredShare));
    // Spread over the causal time kernel [opl, opl + w] (beam_settings.h).
    recorder.addPulsed(opl, opl + maps_.surfaceTimeWidth,
                       s.throughput * f * photon.power * float(norm * (before ? gate.beforeWeight : 1.0)),
                       scene.emitters()[photon.emitter]->pulse());
  }
}

}  // namespace femto::beams
