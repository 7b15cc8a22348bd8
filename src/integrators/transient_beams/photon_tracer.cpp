#include <transient_beams/photon_tracer.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <type_traits>

#include <femto/base/thread_edges.h>
#include <femto/loop/tile_distribution.h>
#include <femto/math/pcg32.h>
#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>
#include <femto/render/medium.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/render/shape.h>
#include <femto/transport/optical_path.h>
#include <femto/transport/volumetric.h>
#include <transient_beams/beam_roulette.h>
#include <transient_beams/boundary_extension.h>
#include <transient_beams/medium_extent.h>

namespace femto::beams {
namespace {

/// Beams name their emitter and depth in 16 bits each.
constexpr size_t MaxEmitters = 65535;
constexpr int MaxPhotonDepth = 32767;
static_assert(sizeof(Beam) <= 88, "a beam should stay under two cache lines");
/// Photons per parallel work item: outputs are concatenated in item order.
constexpr uint64_t PhotonsPerBlock = 1024;

/// The random numbers of one photon: a PCG32 stream restarted per photon
/// from (pass seed, photon index), so the photon is the same on any thread.
class PhotonSampler final : public Sampler {
 public:
  PhotonSampler() : Sampler(Properties()) {}
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<PhotonSampler>(); }
  void startPixel(uint64_t seed, uint64_t index) override { rng_.seed(mixSeed(seed, index), index); }
  void advance() override {}
  float next1D() override { return rng_.nextFloat(); }
  Point2f next2D() override {
    float u = rng_.nextFloat();
    return {u, rng_.nextFloat()};
  }
  std::string toString() const override { return "PhotonSampler"; }

 private:
  PCG32 rng_;
};

/// Emitters weighted by their total power (average over channels).
Distribution1D emitterPowerDistribution(const Scene& scene) {
  std::vector<float> weights;
  for (const auto& emitter : scene.emitters()) weights.push_back(std::max(0.0f, emitter->power().average()));
  if (weights.empty()) return Distribution1D();
  return Distribution1D(std::move(weights));
}

/// Emitters at infinity (directional, constant, envmap) have no flag of
/// their own; their direction samples have an infinite distance
/// (SceneSphere::directionSample), which marks them.
bool isAtInfinity(const Emitter& emitter, const Point3f& ref) {
  DirectionSample ds;
  emitter.sampleDirection(ref, Point2f(0.5f), ds);
  return ds.dist == Infinity;
}

/// A photon point's power in beam units (ray_point.h): the power arriving at
/// a free-flight event times T(t)/p(t), i.e. MediumSample::weight
/// (sigma_s T/p) over sigma_s. Then sum_i Phi_i delta(x - x_i) has the
/// expectation of the beams' sum_b Phi_b T_b(s) delta_line, and both
/// estimators multiply by sigma_s where the camera ray meets the light. A
/// channel that cannot scatter (sigma_s = 0, hence weight 0) stays 0.
Color3f pointPower(const Color3f& arriving, const Color3f& weight, const Color3f& sigmaS) {
  Color3f p;
  for (int c = 0; c < 3; ++c) p[c] = sigmaS[c] > 0.0f ? arriving[c] * weight[c] / sigmaS[c] : 0.0f;
  return p.isValid() ? p : Color3f(0.0f);
}

}  // namespace

PhotonTracer::PhotonTracer(const Scene& scene, const BeamSettings& settings, double horizon)
    : scene_(scene),
      settings_(settings),
      horizon_(horizon),
      reach_(std::isfinite(horizon) ? cameraReach(scene, settings.observerTime) : CameraReach{}),
      // Radii shrink pass by pass: pass 0's bound every pass. The surface
      // radius may still be the scene's default before pass 0 derives it,
      // which stays within 4 times that (surface_radius_rule.h); without
      // smooth surfaces no photon lands on one.
      kernelReach_(settings.radius > 0.0f ? double(settings.radius) + (scene.hasSmoothSurfaces()
                                                                           ? (settings.surfaceRadiusFinal ? 1.0 : 4.0) *
                                                                                 double(settings.surfaceRadius)
                                                                           : 0.0)
                                          : Infinity),
      emitterPower_(emitterPowerDistribution(scene)),
      sampler_(std::make_unique<PhotonSampler>()),
      levels_(settings.timeSplitting && settings.timeLevels && std::isfinite(horizon) ? settings.timeLevels.get()
                                                                                     : nullptr) {
  for (const auto& emitter : scene.emitters()) atInfinity_.push_back(isAtInfinity(*emitter, scene.bbox().center()));
}

PhotonTracer::~PhotonTracer() = default;

/// The state of one photon: where it is and its OPL there (OpticalPath), and what it carries.
struct PhotonTracer::Photon : OpticalPath {
  Color3f power{0.0f};
  float startLevel = 0.0f;           // power.maxValue() when emitted (Russian roulette)
  int depth = 1;                     // segment being travelled (1: leaving the emitter)
  uint16_t emitter = 0;              // index of the emitter that sent it
  bool scattered = false;            // scattered in a medium or off a non-specular surface
  bool indirect = false;             // scattered, or bounced off a specular surface
  bool clockAtFirstSurface = false;  // from an emitter at infinity: OPL 0 where it first meets a surface
  float startExtension = 0.0f;       // the next beam's Beam::before: it starts on a boundary (boundary_extension.h)
  Vec3f startOffsetDelay{0.0f};      // the next beam's Beam::offsetDelay (entered through an index change)
  float lastLeg = 0.0f;              // length of the segment that reached the current surface (SurfacePhoton::leg)
  int splitProduct = 1;              // time_splitting: the product of its split factors so far
};

/// A copy split off at a scattering vertex: it samples its own direction on
/// from there (on `si` when `onSurface`, else from its vertex in its medium).
struct PhotonTracer::Pending {
  Photon photon;
  SurfaceInteraction si;
  bool onSurface = false;
};

void PhotonTracer::trace(uint64_t seed, uint64_t index, std::vector<Beam>& beams, std::vector<SurfacePhoton>& photons,
                         bool storeBeams) {
  if (emitterPower_.size() == 0 || !(emitterPower_.integral() > 0.0f)) return;
  Sampler& sampler = *sampler_;
  sampler.startPixel(seed, index);
  Photon ph;
  if (!emit(ph, sampler, index)) return;
  pending_.clear();
  follow(ph, sampler, beams, photons, storeBeams);
  // Copies split off on the way (time_splitting), each from where it split,
  // on the photon's own stream: the same whatever the thread.
  while (!pending_.empty()) {
    Pending p = pending_.back();
    pending_.pop_back();
    if (p.onSurface ? leaveSurface(p.photon, p.si, sampler) : leaveMediumVertex(p.photon, sampler))
      follow(p.photon, sampler, beams, photons, storeBeams);
  }
}

void PhotonTracer::follow(Photon& ph, Sampler& sampler, std::vector<Beam>& beams, std::vector<SurfacePhoton>& photons,
                          bool storeBeams) {
  // The camera adds at least one segment to every photon path: a photon
  // segment `depth` ends paths of at least depth + 1 segments.
  for (int passThrough = 0;
       passThrough < MaxPassThrough && ph.depth < MaxPhotonDepth && settings_.depthAllowed(ph.depth + 1);) {
    SurfaceInteraction si;
    bool hit = scene_.rayIntersect(ph.ray, si);
    if (ph.medium) {
      // Beams and points (zero-length beams at scattering vertices) obey the same store rule.
      const bool store = storeBeams && (settings_.store == BeamStore::All || !ph.scattered);
      Color3f arriving;
      const MediumSample ms = crossMedium(ph, hit, si, store, sampler, beams, arriving);
      if (ph.power.isBlack()) return;
      if (ms.scattered) {
        if (!scatterInMedium(ph, ms, arriving, store, sampler, beams)) return;
        passThrough = 0;
        continue;
      }
    }
    if (!hit || !reachSurface(ph, si)) return;
    if (isPassThrough(si)) {
      const Medium* from = ph.medium;
      const float etaFrom = ph.eta();
      ph.crossBoundary(si);
      // Entering a medium through its boundary: the next beam starts there.
      const bool entered = ph.medium && ph.medium != from;
      ph.startExtension = entered ? boundaryExtension(si.n, ph.ray.d) : 0.0f;
      ph.startOffsetDelay = entered ? boundaryOffsetDelay(si.n, ph.ray.d, ph.eta() - etaFrom) : Vec3f(0.0f);
      ++passThrough;
      continue;
    }
    if (!scatterOnSurface(ph, si, sampler, photons)) return;
    passThrough = 0;
  }
}

Point2f stratifiedDirection(uint64_t index, uint64_t beamPhotons, uint64_t photons, const Point2f& jitter) {
  // The beam photons [0, beamPhotons) and the rest are stratified apart:
  // each group's estimates then sum one photon per stratum.
  const bool beams = index < beamPhotons;
  const uint64_t group = beams ? beamPhotons : (photons > beamPhotons ? photons - beamPhotons : 0);
  const uint64_t j = beams ? index : index - beamPhotons;
  const uint64_t k = uint64_t(std::sqrt(double(group)));  // k x k strata
  if (k == 0 || j >= k * k) return jitter;               // the group's last photons: not stratified
  return Point2f((float(j % k) + jitter.x) / float(k), (float(j / k) + jitter.y) / float(k));
}

bool PhotonTracer::emit(Photon& ph, Sampler& sampler, uint64_t index) const {
  const float uPick = sampler.next1D();
  const Point2f uPosition = sampler.next2D();
  Point2f uDirection = sampler.next2D();
  if (settings_.stratifiedPhotons)
    uDirection = stratifiedDirection(index, uint64_t(settings_.beamPhotons()), uint64_t(settings_.photonCount),
                                     uDirection);
  float pick = 0.0f;
  const size_t emitterIndex = emitterPower_.sampleDiscrete(uPick, &pick);
  const Emitter& emitter = *scene_.emitters()[emitterIndex];
  ph.emitter = uint16_t(emitterIndex);
  ph.power = emitter.sampleRay(uPosition, uDirection, ph.ray) / pick;
  // Emitted at OPL 0: the camera side reports every contribution with the
  // pulse of the emitter the photon names, and the film convolves exactly.
  ph.opl = 0.0;
  // Light from infinitely far away has no finite path: transient_path's
  // next-event estimation counts a shadow ray toward such an emitter only up
  // to the last surface it crosses (transport/volumetric.cpp, connect), i.e.
  // its light is at OPL 0 on the outermost surface toward the emitter. A
  // photon from the emission disk first meets exactly that surface, so its
  // clock starts there rather than on the disk (which would delay it by the
  // disk's distance, an artefact of where the disk is placed).
  ph.clockAtFirstSurface = atInfinity_[emitterIndex];
  if (ph.power.isBlack() || !ph.power.isValid()) return false;
  // The medium the scene puts the emitter in (Mitsuba 0.6's
  // <emitter><ref id="fog"/></emitter>), else the one its geometry implies.
  ph.medium = emitter.medium() ? emitter.medium() : mediumAround(scene_, ph.ray);
  ph.vertex = ph.ray.o;
  ph.startLevel = ph.power.maxValue();
  return true;
}

MediumSample PhotonTracer::crossMedium(Photon& ph, bool hit, const SurfaceInteraction& si, bool store, Sampler& sampler,
                                       std::vector<Beam>& beams, Color3f& arriving) const {
  // Long beams end by Russian roulette once their transmittance is low
  // (beam_roulette.h); the camera side weights them by 1 / survival. Drawn
  // whether or not the beam is stored, so that a photon's path does not
  // depend on which of its segments leave beams.
  const BeamRoulette roulette = BeamRoulette::of(*ph.medium);
  const float rouletteLength = roulette.active() ? roulette.sampleLength(sampler.next1D()) : Infinity;
  if (store && settings_.volumeEstimator != VolumeEstimator::Points) {
    // From the exact vertex, so the beam's OPL and geometry agree.
    const float toSurface = hit ? distance(ph.vertex, si.p) : unboundedSegmentLength(*ph.medium, ph.opl, horizon_);
    float length = std::min(toSurface, rouletteLength);
    // Past where its light can no longer land in the window, the beam ends (CameraReach).
    bool cut = false;
    if (!ph.clockAtFirstSurface && std::isfinite(length)) {
      const float reachable = reachableLength(reach_, ph.vertex, ph.ray.d, length, ph.opl, ph.eta(), reachLimit(ph.eta()));
      cut = reachable < length, length = reachable;
    }
    if (length > 0.0f && std::isfinite(length)) {
      Beam beam{ph.vertex, ph.ray.d, length, ph.power, ph.opl, ph.eta(), int16_t(ph.depth), ph.emitter, ph.medium};
      // Ending on a boundary of its medium (not by the roulette): extended past it.
      beam.before = ph.startExtension;
      beam.offsetDelay = ph.startOffsetDelay;
      if (hit && !cut && !(rouletteLength < toSurface) && !sameMediumAcross(si, ph.ray.d, ph.medium))
        beam.after = boundaryExtension(si.n, ph.ray.d);
      beams.push_back(beam);
    }
  }
  ph.startExtension = 0.0f;
  ph.startOffsetDelay = Vec3f(0.0f);
  MediumSample ms = ph.medium->sampleDistance(ph.ray, hit ? si.t : Infinity, sampler);
  arriving = ph.power;
  ph.power *= ms.weight;
  return ms;
}

bool PhotonTracer::scatterInMedium(Photon& ph, const MediumSample& ms, const Color3f& arriving, bool store,
                                   Sampler& sampler, std::vector<Beam>& beams) {
  const Medium& medium = *ph.medium;
  ph.advance(ms.p);
  // A photon point: the light arriving here, before this vertex's delay and phase sampling.
  if (store && settings_.volumeEstimator == VolumeEstimator::Points && ph.opl < horizon_) {
    const Color3f point = pointPower(arriving, ms.weight, medium.scatteringCoefficient(ms.p));
    if (!point.isBlack())
      beams.push_back(Beam{ms.p, ph.ray.d, 0.0f, point, ph.opl, ph.eta(), int16_t(ph.depth), ph.emitter, &medium});
  }
  const PhaseFunction& phase = medium.phase();
  if (phase.hasDelay()) ph.opl += phase.sampleDelay(sampler.next1D());
  if (!(ph.opl < horizon_) || !inReach(ph)) return false;
  split(ph, nullptr);
  return leaveMediumVertex(ph, sampler);
}

bool PhotonTracer::leaveMediumVertex(Photon& ph, Sampler& sampler) const {
  Vec3f wo;
  float pdf = 0.0f;
  float weight = ph.medium->phase().sample(-ph.ray.d, sampler.next2D(), wo, pdf);
  if (!(pdf > 0.0f) || !(weight > 0.0f)) return false;
  ph.power *= weight;
  ph.ray = Ray(ph.vertex, wo);
  ph.scattered = ph.indirect = true;
  ph.clockAtFirstSurface = false;  // (a scene inside an unbounded medium: the clock ran from the disk)
  ++ph.depth;
  return russianRoulette(ph, sampler);
}

double PhotonTracer::reachLimit(float eta) const {
  return reach_.valid && std::isfinite(kernelReach_) ? horizon_ + (double(eta) + 1.0) * kernelReach_ : Infinity;
}

bool PhotonTracer::inReach(const Photon& ph) const {
  // A clock that starts at the first surface has not counted this leg: no bound before it.
  return ph.clockAtFirstSurface || ph.opl + reach_.distance(ph.vertex) < reachLimit(ph.eta());
}

bool PhotonTracer::reachSurface(Photon& ph, const SurfaceInteraction& si) const {
  // A photon from an emitter at infinity starts its clock here (emit).
  const bool counted = !ph.clockAtFirstSurface;
  ph.clockAtFirstSurface = false;
  // An uncounted leg (the clock starts here) is timed as a plane wave.
  ph.lastLeg = counted ? distance(ph.vertex, si.p) : Infinity;
  ph.advance(si.p, counted);
  return ph.opl < horizon_ && inReach(ph);
}

bool PhotonTracer::scatterOnSurface(Photon& ph, const SurfaceInteraction& si, Sampler& sampler,
                                    std::vector<SurfacePhoton>& photons) {
  const BSDF& bsdf = *si.bsdf();
  if (bsdf.hasSmooth() && ph.indirect) {
    Normal3f n = dot(si.n, ph.ray.d) < 0.0f ? si.n : -si.n;
    photons.push_back(SurfacePhoton{si.p, n, -ph.ray.d, ph.power, ph.opl, ph.depth, ph.emitter, ph.lastLeg, ph.eta()});
  }
  // A photon stored above has not scattered here yet: the camera side adds
  // this vertex's delay when it gathers it.
  if (bsdf.hasDelay()) ph.opl += bsdf.sampleDelay(sampler.next1D());
  split(ph, &si);
  return leaveSurface(ph, si, sampler);
}

bool PhotonTracer::leaveSurface(Photon& ph, const SurfaceInteraction& si, Sampler& sampler) const {
  const BSDF& bsdf = *si.bsdf();
  BSDFSample bs;
  Color3f weight = bsdf.sample(si, sampler.next1D(), sampler.next2D(), bs, TransportMode::Importance);
  if (!(bs.pdf > 0.0f) || weight.isBlack()) return false;
  Vec3f wo = si.toWorld(bs.wo);
  ph.power *= weight;
  ph.leaveSurface(si, wo, bs.eta);
  // Leaving a boundary of the medium it is now in: the next beam starts there.
  ph.startExtension = ph.medium && !sameMediumAcross(si, -wo, ph.medium) ? boundaryExtension(si.n, wo) : 0.0f;
  ph.startOffsetDelay = Vec3f(0.0f);  // refraction keeps the wavefront across the beam (phase matching)
  if (bs.sampledFlags & BSDFFlags::Delta)
    ph.indirect = true;
  else
    ph.scattered = ph.indirect = true;
  ++ph.depth;
  return russianRoulette(ph, sampler);
}

float PhotonTracer::timeLevel(const Photon& ph) const {
  if (!levels_ || ph.clockAtFirstSurface) return 1.0f;
  // Its light reaches the camera no earlier than the straight way there (CameraReach).
  return levels_->atFilm(ph.opl + (reach_.valid ? double(reach_.distance(ph.vertex)) : 0.0));
}

void PhotonTracer::split(Photon& ph, const SurfaceInteraction* si) {
  if (!levels_) return;
  const int n = TimeLevels::splitCount(ph.power.maxValue() / ph.startLevel / timeLevel(ph), ph.splitProduct);
  if (n < 2) return;
  ph.power = ph.power / float(n);
  ph.splitProduct *= n;
  for (int k = 1; k < n; ++k) pending_.push_back(Pending{ph, si ? *si : SurfaceInteraction(), si != nullptr});
}

bool PhotonTracer::russianRoulette(Photon& ph, Sampler& sampler) const {
  if (ph.depth <= settings_.rrDepth) return true;
  // Survival in proportion to the power left of what the photon started
  // with, over the time level (time_splitting; 1 without).
  float q = std::min(ph.power.maxValue() / ph.startLevel / timeLevel(ph), 0.95f);
  if (!(sampler.next1D() < q)) return false;
  ph.power = ph.power / q;
  return true;
}

namespace {

/// The scene's media in an order every rank builds the same way (sensor,
/// emitters, shapes' interiors and exteriors): beams name theirs by index.
std::vector<const Medium*> sceneMedia(const Scene& scene) {
  std::vector<const Medium*> media;
  auto add = [&](const Medium* m) {
    if (m && std::find(media.begin(), media.end(), m) == media.end()) media.push_back(m);
  };
  add(scene.sensor().medium());
  for (const auto& e : scene.emitters()) add(e->medium());
  for (const auto& s : scene.shapes()) add(s->interiorMedium()), add(s->exteriorMedium());
  return media;
}

template <typename T>
void appendBytes(std::vector<char>& out, const T* data, size_t count) {
  const char* p = reinterpret_cast<const char*>(data);
  out.insert(out.end(), p, p + count * sizeof(T));
}

}  // namespace

bool exchangePhotons(const Scene& scene, TileDistribution& job, const std::vector<Beam>& beams,
                     const std::vector<SurfacePhoton>& photons, PhotonPass& pass) {
  static_assert(std::is_trivially_copyable_v<Beam> && std::is_trivially_copyable_v<SurfacePhoton>);
  const std::vector<const Medium*> media = sceneMedia(scene);
  std::vector<uint32_t> mediumIndex(beams.size());
  bool named = true;
  for (size_t i = 0; i < beams.size(); ++i) {
    auto it = std::find(media.begin(), media.end(), beams[i].medium);
    named &= it != media.end();
    mediumIndex[i] = uint32_t(it - media.begin());
  }
  // Every rank must take the same way: agree first.
  const std::vector<char> flags = job.gatherAll(std::vector<char>{char(named)});
  if (std::find(flags.begin(), flags.end(), char(0)) != flags.end()) return false;
  std::vector<char> mine;
  const uint64_t counts[2] = {beams.size(), photons.size()};
  appendBytes(mine, counts, 2);
  appendBytes(mine, beams.data(), beams.size());
  appendBytes(mine, mediumIndex.data(), mediumIndex.size());
  appendBytes(mine, photons.data(), photons.size());
  const std::vector<char> all = job.gatherAll(mine);
  // Rank by rank, in rank order: the blocks' order.
  for (size_t at = 0; at < all.size();) {
    uint64_t n[2];
    std::memcpy(n, all.data() + at, sizeof n);
    at += sizeof n;
    const size_t firstBeam = pass.beams.size();
    pass.beams.resize(firstBeam + n[0]);
    std::memcpy(static_cast<void*>(pass.beams.data() + firstBeam), all.data() + at, n[0] * sizeof(Beam));
    at += n[0] * sizeof(Beam);
    for (uint64_t i = 0; i < n[0]; ++i) {
      uint32_t m;
      std::memcpy(&m, all.data() + at + i * sizeof m, sizeof m);
      pass.beams[firstBeam + i].medium = media.at(m);
    }
    at += n[0] * sizeof(uint32_t);
    const size_t firstPhoton = pass.surfacePhotons.size();
    pass.surfacePhotons.resize(firstPhoton + n[1]);
    std::memcpy(static_cast<void*>(pass.surfacePhotons.data() + firstPhoton), all.data() + at,
                n[1] * sizeof(SurfacePhoton));
    at += n[1] * sizeof(SurfacePhoton);
  }
  return true;
}

PhotonPass tracePhotonPass(const Scene& scene, const BeamSettings& settings, uint64_t seed, double horizon) {
  if (scene.emitters().size() > MaxEmitters)
    throw Error(settings.location, str("transient_beams: the scene has ", scene.emitters().size(),
                                       " emitters; photons can name at most ", MaxEmitters));
  const auto start = std::chrono::steady_clock::now();
  PhotonPass pass;
  pass.photonCount = uint64_t(settings.photonCount);
  pass.beamPhotonCount = uint64_t(settings.beamPhotons());
  // Photons past the beam photons only leave surface photons: where no
  // surface stores one (media behind index-matched boundaries, delta
  // surfaces) they are not traced. Each photon has its own random stream, so
  // the beams are the same either way.
  pass.tracedPhotons = scene.hasSmoothSurfaces() ? pass.photonCount : pass.beamPhotonCount;
  const uint64_t blocks = (pass.tracedPhotons + PhotonsPerBlock - 1) / PhotonsPerBlock;
  struct Block {
    std::vector<Beam> beams;
    std::vector<SurfacePhoton> photons;
  };
  std::vector<Block> out(blocks);
  auto traceBlock = [&](uint64_t b) {
    // One tracer per block: cheap to make, and no thread-local state to share.
    PhotonTracer tracer(scene, settings, horizon);
    const uint64_t end = std::min(pass.tracedPhotons, (b + 1) * PhotonsPerBlock);
    for (uint64_t i = b * PhotonsPerBlock; i < end; ++i)
      tracer.trace(seed, i, out[b].beams, out[b].photons, i < pass.beamPhotonCount);
  };
  auto traceBlocks = [&](uint64_t first, uint64_t last) {
    ForkJoinEdges edges;
    tbb::parallel_for(first, last, edges.task(traceBlock));
    edges.join();
  };
  // Under mpirun each rank traces a contiguous share of the blocks and the
  // ranks exchange them (photons are seeded by index and concatenated in
  // block order, so every rank then holds what one process traces).
  TileDistribution* job = tileDistribution();
  const uint64_t ranks = job ? uint64_t(job->ranks()) : 1, rank = job ? uint64_t(job->rank()) : 0;
  if (ranks > 1) {
    const uint64_t first = blocks * rank / ranks, last = blocks * (rank + 1) / ranks;
    traceBlocks(first, last);
    std::vector<Beam> beams;
    std::vector<SurfacePhoton> photons;
    for (uint64_t b = first; b < last; ++b) {
      beams.insert(beams.end(), out[b].beams.begin(), out[b].beams.end());
      photons.insert(photons.end(), out[b].photons.begin(), out[b].photons.end());
    }
    if (exchangePhotons(scene, *job, beams, photons, pass)) {
      pass.traceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return pass;
    }
    // A beam in a medium the exchange cannot name: every rank traces the others' blocks too.
    traceBlocks(0, first);
    traceBlocks(last, blocks);
  } else {
    traceBlocks(0, blocks);
  }
  size_t beamCount = 0, photonCount = 0;
  for (const Block& b : out) beamCount += b.beams.size(), photonCount += b.photons.size();
  pass.beams.reserve(beamCount);
  pass.surfacePhotons.reserve(photonCount);
  for (Block& b : out) {
    pass.beams.insert(pass.beams.end(), b.beams.begin(), b.beams.end());
    pass.surfacePhotons.insert(pass.surfacePhotons.end(), b.photons.begin(), b.photons.end());
    b = Block();
  }
  pass.traceSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return pass;
}

}  // namespace femto::beams
