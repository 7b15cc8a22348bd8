// transient_path: unidirectional volumetric path tracing that reports every
// contribution with the optical path length (OPL, time/time_grid.h) at which it
// reaches the sensor, so one integrator renders transient and steady films
// (the transient RTE of Marco et al., "Transient Photon Beams", eq. 1-3).
// Each scattering vertex connects one emitter sample through media, combined
// with phase/BSDF sampling by the power heuristic (Veach 1997, sec. 9.2.4);
// toward point lights it adds an equiangular vertex on the segment and a
// light-directed vertex (direction density ~ 1/sin of the angle to the light),
// whose three-way MIS removes the fireflies of a point light in fog.
// time_gating samples toward the film's window (DARTS, He et al. 2024).
// time_splitting: Russian roulette and splitting against the film's time
// profile, read from a pilot of camera samples (a weight window, as in
// adjoint-driven roulette and splitting, Vorba and Krivanek 2016, with the
// bins a path can still reach in place of the pixel's value).
// Why each strategy and how they combine: docs/design/transient-path.md;
// what they buy: docs/BENCHMARKS.md, "transient_path sampling". Mitsuba's
// volpath loads as this integrator; the same source builds mitransient's
// transient_prbvolpath (max_depth 6 by default) and Mitsuba 2's transientpath,
// bit for bit the same output (docs/design/transient-path.md, "mitransient's").
//
// clang-format off
// | name                 | type    | default | meaning                                                      | unit |
// |----------------------|---------|---------|--------------------------------------------------------------|------|
// | max_depth            | integer | -1      | longest path in segments (-1: no limit)                      | -    |
// | rr_depth             | integer | 5       | depth from which Russian roulette may end paths              | -    |
// | hide_emitters        | boolean | false   | emitters seen directly by the camera appear black            | -    |
// | observer_time        | boolean | true    | include the camera segment in the OPL                        | -    |
// | equiangular          | boolean | true    | equiangular next-event vertices toward point lights (false: free flights only, for comparisons) | - |
// | light_directions     | boolean | true    | a second next-event vertex per scattering vertex, along a direction sampled around point lights, and the surface that direction ends on (needs equiangular) | - |
// | time_gating          | boolean | true    | sample next-event distances toward point lights inside the film's time window, truncate free flights past it (false: every sample independent of the window, as before) | - |
// | time_splitting       | boolean | true    | transient films: roulette and split paths against the film's time profile (a pilot of up to 4096 camera samples, a quarter of a pass's at most), so late bins get as many paths as early ones (false: Mitsuba's roulette on the throughput) | - |
// | before_window_rate   | float   | 0.125   | with time_gating: the share of next-event connections whose light arrives before the window that are made (weighted by its inverse) | - |
// | skip_before_window   | boolean | false   | with time_gating: before_window_rate = 0 (steady and _before then lack that light) | - |
// | camera_unwarp        | boolean | false   | mitransient's name for observer_time = false                 | -    |
// | temporal_filter      | string  | ""      | mitransient: the film's time filter: "" (the film's own), "box", "gaussian" | - |
// | gaussian_stddev      | float   | 2       | mitransient: its standard deviation                          | bins |
// | discard_direct_light | boolean | false   | mitransient: drop emission that phase/BSDF sampling (or the camera ray) finds; next-event estimates stay | - |
// | version              | integer | -       | lajolla's volpath variant selector: accepted, ignored        | -    |
// | block_size           | integer | 0       | mitransient's tile size: accepted, ignored (femto picks its tiles) | - |
// clang-format on
#include <algorithm>
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/film/transient_film.h>
#include <femto/film/transient_render.h>
#include <femto/film/transient_tile.h>
#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>
#include <femto/render/medium.h>
#include <femto/render/path_depth.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/transient_integrator.h>
#include <femto/time/time_levels.h>
#include <femto/transport/direct_lighting.h>
#include <femto/transport/equiangular.h>
#include <femto/transport/optical_path.h>
#include <femto/transport/point_directions.h>
#include <femto/transport/time_gate.h>
#include <femto/transport/transient_emission.h>
#include <femto/transport/volumetric.h>

namespace femto {
namespace {

/// Residual-time truncation of one medium segment (time gating): past
/// `reach` a vertex cannot contribute before the gate ends
/// (transport/time_gate.h, gateReach); `probability` is free flights' chance
/// to scatter before it (homogeneous media). Inactive when reach >= the
/// segment's length.
struct GatedSegment {
  float reach = Infinity;
  float probability = 1.0f;
  bool truncates(float tMax) const { return reach < tMax; }
  /// Density of the (truncated) free flight at t, given the untruncated one.
  float pdf(float tMax, float t, float freeFlightPdf) const {
    if (!truncates(tMax)) return freeFlightPdf;
    return t < reach && probability > 0.0f ? freeFlightPdf / probability : 0.0f;
  }
};

/// The mutable state of one camera path: where it is and its OPL there
/// (OpticalPath: ray, vertex, opl, medium, surfaceEta), and what it carries.
struct PathState : OpticalPath {
  bool cameraSegment = true;  // no scattering vertex yet
  Color3f throughput{1.0f};
  float etaScale = 1.0f;  // product of squared relative IORs (for Russian roulette)
  int depth = 0;          // segments so far
  // The last scattering vertex, for weighting emission that phase/BSDF sampling
  // finds (a camera ray counts as delta: no other strategy finds what it sees).
  ScatterOrigin prev;
  // The medium segment `ray` is crossing, when next-event
  // estimation samples distances along it toward point lights: its length
  // (hit distance or Infinity).
  bool equiangular = false;
  float segmentMax = 0.0f;
  // The equiangular segment toward the light last asked for on this medium
  // segment: its equiangular vertex and its free-flight vertex's MIS weight
  // need the same one (atan2s and, gated, the window's ellipsoids), and the
  // weight is computed by a function that only reads the path.
  struct EquiangularCache {
    bool valid = false;
    Point3f light;
    EquiangularSegment segment;
  };
  mutable EquiangularCache equiangularCache;
  // Whether `ray` continues straight from the scattering vertex `prev` (not
  // from the camera) through index-matched boundaries and homogeneous media
  // only, and that vertex also sampled a light-directed vertex: then that
  // strategy could have made a vertex on this segment too. passProbability:
  // the probability that free flights crossed the segments since `prev`
  // without scattering (what the light-directed vertex's density is compared with).
  bool segmentFromVertex = false;
  bool prevLightDirected = false;
  float passProbability = 1.0f;
  // Whether those segments included a medium one (lightDirectedSurface).
  bool crossedMedium = false;
  // Time gating: the OPL window contributions must reach, and the OPL where
  // the segment starts when it counts toward the OPL (else -Infinity: no gate).
  OplGate gate;
  double segmentStartOpl = -Infinity;
  // Residual-time truncation (time gating): where the lights are, and the
  // distance along the current medium segment past which nothing reaches the
  // gate (GatedSegment).
  LightBound lights;
  GatedSegment gated;
  // The largest refractive index of the scene's media (and 1): light
  // connections arrive at most that times their length after they start.
  float etaMax = 1.0f;
  // time_splitting: the product of the split factors so far (at most MaxSplitProduct).
  int splitProduct = 1;
};

}  // namespace

/// Defaults that differ between the names this integrator is known by.
struct TransientPathDefaults {
  int maxDepth = -1;
};

class TransientPathIntegrator : public TransientIntegrator {
 public:
  explicit TransientPathIntegrator(const Properties& props, const TransientPathDefaults& defaults = {})
      : depth_(PathDepthSettings::read(props, defaults.maxDepth)),
        hideEmitters_(props.getBool("hide_emitters", false)),
        observerTime_(props.getBool("observer_time", true)),
        equiangular_(props.getBool("equiangular", true)),
        lightDirections_(props.getBool("light_directions", true)),
        timeGating_(props.getBool("time_gating", true)),
        timeSplitting_(props.getBool("time_splitting", true)),
        beforeWindowRate_(props.getFloat("before_window_rate", DefaultBeforeWindowRate)) {
    if (props.getBool("skip_before_window", false)) {
      if (!timeGating_)
        props.raise("skip_before_window",
                    "skip_before_window needs time_gating = true (it skips light before its window)");
      if (props.has("before_window_rate"))
        props.raise("skip_before_window",
                    "give either skip_before_window or before_window_rate (skip = rate 0), not both");
      beforeWindowRate_ = 0.0f;
    }
    if (!(beforeWindowRate_ >= 0.0f && beforeWindowRate_ <= 1.0f))
      props.raise("before_window_rate", str("before_window_rate must be in [0, 1], got ", beforeWindowRate_));
    // mitransient's spelling: camera_unwarp = true removes the camera segment.
    if (props.has("camera_unwarp")) {
      if (props.has("observer_time"))
        props.raise("camera_unwarp", "give either observer_time or camera_unwarp (its opposite), not both");
      observerTime_ = !props.getBool("camera_unwarp");
    }
    readTemporalFilter(props);
    discardDirectLight_ = props.getBool("discard_direct_light", false);
    props.getInt("version", 0);     // lajolla's volpath scenes select their homework variant with it
    props.getInt("block_size", 0);  // mitransient's tile size in scalar mode: femto picks its own tiles
  }

  /// With time_splitting on a transient film: the pilot's profile first
  /// (pilotTimeProfile), then the render by a copy of this integrator that holds it.
  RenderStats render(const Scene& scene, const RenderOptions& options) const override {
    const auto* film = dynamic_cast<const TransientFilm*>(&scene.sensor().film());
    if (!timeSplitting_ || !film || depth_.maxDepth == 0) return TransientIntegrator::render(scene, options);
    auto configured = std::make_shared<TransientPathIntegrator>(*this);
    configured->levels_ = pilotTimeLevels(scene, *film, *this, options.seed ^ PilotSeedSalt, options.threads);
    std::shared_ptr<const TransientIntegrator> integrator = configured;
    return renderTransientPasses(scene, options, 1, [&](int, double) { return integrator; });
  }

  void sample(const Scene& scene, const Ray& cameraRay, Sampler& sampler, RadianceRecorder& recorder) const override {
    if (depth_.maxDepth == 0) return;
    PathState s;
    s.ray = cameraRay;
    s.medium = scene.sensor().medium();
    s.vertex = s.prev.p = cameraRay.o;
    if (timeGating_) {
      s.gate = oplGate(scene, recorder);
      s.lights = lightBound(scene);
      s.etaMax = scene.largestMediumEta();
    }
    trace(scene, s, sampler, recorder);
  }

  bool countsCameraSegment() const override { return observerTime_; }

  std::string toString() const override {
    return str("TransientPathIntegrator[", depth_.toString(), ", hide_emitters=", hideEmitters_ ? "true" : "false",
               ", observer_time=", observerTime_ ? "true" : "false", ", equiangular=", equiangular_ ? "true" : "false",
               ", light_directions=", lightDirections_ ? "true" : "false",
               ", time_gating=", timeGating_ ? "true" : "false", ", time_splitting=", timeSplitting_ ? "true" : "false",
               ", before_window_rate=", beforeWindowRate_, "]");
  }

 private:
  /// Follow path `s` from its current ray until it ends (split copies follow
  /// their own, scatterInMedium / scatterOnSurface).
  void trace(const Scene& scene, PathState& s, Sampler& sampler, RadianceRecorder& recorder) const {
    const double horizon = recorder.horizon();
    for (int passThrough = 0; passThrough < MaxPassThrough;) {
      // The surface's interaction only once the path reaches it (PreliminaryHit).
      PreliminaryHit hitAhead;
      bool hit = scene.rayIntersectPreliminary(s.ray, hitAhead);
      MediumSample ms;
      if (s.medium) {
        beginMediumSegment(s, hitAhead.t);
        if (s.equiangular) nextEventEquiangular(scene, s, sampler, recorder);
        ms = sampleFreeFlight(s, hitAhead.t, sampler);
        s.throughput *= ms.weight;
        if (s.throughput.isBlack()) return;
        if (!ms.scattered) passSegment(s, hitAhead.t, sampler);
      }
      if (ms.scattered) {
        if (!advance(s, ms.p) || s.opl >= horizon || pastGate(s)) return;
        if (!scatterInMedium(scene, s, ms.p, ms.t, sampler, recorder)) return;
        passThrough = 0;
        continue;
      }
      if (!hit) {
        if (!(hideEmitters_ && s.depth == 0) && !discardDirectLight_)
          recordEnvironmentEmission(scene, s.ray, s.prev, s.opl, s.throughput, recorder);
        return;
      }
      SurfaceInteraction si;
      scene.computeInteraction(s.ray, hitAhead, si);
      if (!advance(s, si.p) || s.opl >= horizon) return;
      recordEmission(scene, s, si, recorder);
      if (pastGate(s, !isPassThrough(si))) return;
      s.equiangular = false;
      if (isPassThrough(si)) {
        s.crossBoundary(si);
        ++passThrough;
        continue;
      }
      if (!scatterOnSurface(scene, s, si, sampler, recorder)) return;
      passThrough = 0;
    }
  }

  /// Move the path to vertex `p` along the current ray, adding the segment's
  /// OPL (unless it is the camera segment and observer time is off).
  bool advance(PathState& s, const Point3f& p) const {
    return s.advance(p, segmentCounts(observerTime_, s.cameraSegment));
  }

  /// A real scattering vertex was reached: count the segment toward
  /// max_depth; false when the path may not scatter again.
  bool enterScatteringVertex(PathState& s) const {
    s.cameraSegment = false;
    return ++s.depth != depth_.maxDepth;
  }

  /// Emission of the surface the path reached, MIS-weighted against emitter
  /// sampling at the previous scattering vertex (shared with `path`).
  void recordEmission(const Scene& scene, const PathState& s, const SurfaceInteraction& si,
                      RadianceRecorder& recorder) const {
    if (!si.emitter() || (hideEmitters_ && s.depth == 0) || discardDirectLight_) return;
    recordSurfaceEmission(scene, si, s.ray.d, distance(s.prev.p, si.p), s.prev, s.opl, s.throughput, recorder);
  }

  /// Next-event estimation from vertex `ref` (a surface, or a medium point
  /// with zero normal): samples an emitter, connects to it through media and
  /// records f * Le * T / pdf, MIS-weighted, at the OPL of the whole path.
  /// `f` gives (value, density of the vertex's own sampling) for a world direction.
  /// `segmentT` >= 0: `ref` is a free-flight vertex at that distance along
  /// s.ray, whose estimate toward a point light is MIS-weighted against
  /// equiangular sampling of the same segment (nextEventEquiangular).
  template <typename ScatterFn>
  void nextEvent(const Scene& scene, const PathState& s, const SurfaceInteraction& ref, Sampler& sampler,
                 RadianceRecorder& recorder, ScatterFn&& scatter, float segmentT = -1.0f) const {
    DirectionSample ds;
    Color3f emitterWeight = scene.sampleEmitterDirection(ref, sampler.next2D(), ds, false);
    if (!(ds.pdf > 0.0f) || emitterWeight.isBlack()) return;
    float beforeWindow = beforeWindowWeight(s, s.opl, ds.dist, sampler);
    if (!(beforeWindow > 0.0f)) return;
    // The OPL of the light segment is at least its length (eta >= 1): skip what the film cannot show.
    if (std::isfinite(ds.dist) && s.opl + ds.dist >= recorder.horizon()) return;
    float pdf = 0.0f;
    Color3f f = scatter(ds.d, pdf);
    if (f.isBlack()) return;
    float weight = ds.delta ? 1.0f : powerHeuristic(1.0f, ds.pdf, 1.0f, pdf);
    Point3f lightPosition;
    if (segmentT < 0.0f && s.crossedMedium && ds.emitter->deltaPosition(lightPosition)) {
      // A surface vertex the path reached straight from its last scattering
      // vertex, which the light-directed ray from there reaches too
      // (lightDirectedSurface): the two share the light's contribution.
      weight = powerHeuristic(1.0f, lightDirectedRatio(s, lightPosition), 0.0f);
    } else if (segmentT >= 0.0f && s.equiangular && ds.emitter->deltaPosition(lightPosition)) {
      weight = freeFlightVertexWeight(s, lightPosition, segmentT);
    }
    // Weighted before the shadow ray: a heterogeneous medium's free-flight
    // vertex leaves the point light to the equiangular vertex wherever that
    // one can sample (weight 0), and its connection is never made.
    if (!(weight > 0.0f)) return;
    Connection c = connect(scene, ref, ds.d, ds.p, ds.dist, mediumAfter(ref, ds.d, s.medium), s.surfaceEta, sampler);
    if (c.transmittance.isBlack()) return;
    recorder.addPulsed(s.opl + c.opl, s.opl + c.opl,
                       s.throughput * f * emitterWeight * c.transmittance * (weight * beforeWindow),
                       ds.emitter->pulse());
  }

  /// Start crossing a medium segment of length `tMax` along s.ray: decide
  /// whether next-event estimation also samples it equiangularly (when a
  /// vertex on it may still connect to a light: depth).
  void beginMediumSegment(PathState& s, float tMax) const {
    s.equiangular = equiangular_ && s.depth + 1 != depth_.maxDepth;
    s.segmentMax = tMax;
    s.equiangularCache.valid = false;
    s.segmentStartOpl = segmentCounts(observerTime_, s.cameraSegment) ? s.opl : -Infinity;
    s.gated = gatedSegment(s.gate, s.lights, s.ray, s.vertex, tMax, *s.medium, s.segmentStartOpl);
  }

  /// Residual-time truncation of the medium segment [0, tMax] of `ray`
  /// (whose origin may be offset from the exact `vertex`, at OPL `startOpl`):
  /// see GatedSegment. The offset is added to the OPL still available, so
  /// the reach stays a bound for the exact vertex.
  static GatedSegment gatedSegment(const OplGate& gate, const LightBound& lights, const Ray& ray, const Point3f& vertex,
                                   float tMax, const Medium& medium, double startOpl) {
    GatedSegment g;
    if (!gate.gates()) return g;
    double eta = medium.eta();
    double reach = gateReach(ray, eta, startOpl - eta * double(distance(vertex, ray.o)), gate, lights);
    if (!(reach < double(tMax))) return g;
    g.reach = float(reach);
    if (medium.isHomogeneous()) g.probability = medium.scatterProbabilityBefore(g.reach);
    return g;
  }

  /// The free flight along the current medium segment [0, tMax]. With a
  /// residual-time truncation short of tMax (GatedSegment), conditioned on
  /// an event before the reach and weighted by its probability
  /// (Medium::sampleDistanceBefore: exactly in homogeneous media, on the
  /// first tentative collision in heterogeneous ones); a path that passes
  /// the reach ends (zero weight): beyond it nothing arrives before the gate ends.
  MediumSample sampleFreeFlight(const PathState& s, float tMax, Sampler& sampler) const {
    if (!s.gated.truncates(tMax)) return s.medium->sampleDistance(s.ray, tMax, sampler);
    return s.medium->sampleDistanceBefore(s.ray, s.gated.reach, sampler);
  }

  /// Density of the free-flight vertex at distance t on the segment [0, tMax]
  /// of `medium`, truncated by `gated` or not, as the MIS weights of the
  /// equiangular and light-directed vertices count it. A heterogeneous
  /// medium's free flights take no distance an equiangular vertex can sample
  /// (freeFlightVertexWeight, the cutoff split): 0 there.
  static float freeFlightPdf(const GatedSegment& gated, float tMax, const Medium& medium, float t) {
    return medium.isHomogeneous() ? gated.pdf(tMax, t, medium.freeFlightPdf(t)) : 0.0f;
  }
  /// The same on the current segment.
  static float freeFlightPdf(const PathState& s, float t) { return freeFlightPdf(s.gated, s.segmentMax, *s.medium, t); }

  /// Whether the path's vertex can no longer contribute before the gate ends
  /// (time gating: OPL + distance to the nearest light, time_gate.h).
  /// `vertex`: the path scatters there. A boundary the camera segment passes
  /// uncounted (observer time off) is no vertex: the one it scatters at
  /// later may lie nearer a light at the same OPL.
  bool pastGate(const PathState& s, bool vertex = true) const {
    return s.gate.gates() && (vertex || segmentCounts(observerTime_, s.cameraSegment)) &&
           femto::pastGate(s.vertex, s.opl, s.gate, s.lights);
  }

  /// The scene's lights for residual-time truncation (LightBound).
  static LightBound lightBound(const Scene& scene) {
    LightBound bound;
    bound.anywhere = false;
    for (const auto& emitter : scene.emitters()) {
      Point3f p;
      if (!emitter->deltaPosition(p) || bound.count == LightBound::MaxPoints) {
        bound.anywhere = true;
        break;
      }
      bound.points[bound.count++] = p;
    }
    return bound;
  }

  /// The OPLs (for a Dirac emission at 0) from which a contribution can reach
  /// the film's bins: before the window start by the time filter's reach and
  /// the latest pulse emission, up to the recorder's horizon. Everything for
  /// steady films, an unbounded horizon or continuous emission (whose step
  /// reaches every later bin).
  static OplGate oplGate(const Scene& scene, const RadianceRecorder& recorder) {
    OplGate gate;
    const TimeGrid& grid = recorder.timeGrid();
    if (!grid.isTransient() || scene.emitters().empty()) return gate;
    double earliest = Infinity, latest = -Infinity;
    for (const auto& emitter : scene.emitters()) {
      earliest = std::min(earliest, emitter->pulse().earliest());
      latest = std::max(latest, emitter->pulse().latest());
    }
    gate.end = recorder.horizon();
    // horizon = window end + filter reach - earliest emission (pulsedHorizon).
    double filterReach = gate.end - grid.end() + earliest;
    double start = grid.start - filterReach - latest;
    if (std::isfinite(start)) gate.start = start;
    return gate;
  }

  /// The part of the current segment equiangular sampling covers for a light
  /// at `c`: all of it, up to the hit. The same for sampling and for the MIS
  /// weight of free-flight vertices, so the two strategies' weights sum to one.
  /// Without time gating not cut at the film's horizon: the samples would
  /// then depend on the time window, and a render split into windows would no
  /// longer give the bins of one render exactly
  /// (test_transient_time_window_split.cpp). With time gating, only the distances whose straight connection to the
  /// light arrives in the gate (the medium's eta along both pieces; phase
  /// delays and other media make some land outside, which costs variance,
  /// not bias: both strategies use this density).
  EquiangularSegment equiangularToward(const PathState& s, const Point3f& c) const {
    PathState::EquiangularCache& cache = s.equiangularCache;
    if (!cache.valid || !(cache.light == c)) {
      cache.segment = equiangularToward(s.ray, s.segmentMax, *s.medium, s.gate, s.segmentStartOpl, c);
      cache.light = c;
      cache.valid = true;
    }
    return cache.segment;
  }
  /// The same for segment [0, tMax] of `ray` in `medium`, starting at OPL `startOpl`.
  static EquiangularSegment equiangularToward(const Ray& ray, float tMax, const Medium& medium, const OplGate& gate,
                                              double startOpl, const Point3f& c) {
    if (!gate.gates() || !std::isfinite(startOpl)) return equiangularSegment(ray.o, ray.d, tMax, c);
    double eta = medium.eta();
    DistanceRange range =
        distancesArrivingWithin(ray.o, ray.d, c, (gate.start - startOpl) / eta, (gate.end - startOpl) / eta);
    float tStart = float(std::max(range.t0, 0.0)), tEnd = float(std::min(range.t1, double(tMax)));
    return equiangularSegment(ray.o, ray.d, tStart, tEnd, c);
  }

  /// p_light(w) / p_vertex(w) for the current segment's direction w and a
  /// light at `c`: the light-directed strategy's direction density relative
  /// to that of the direction the vertex sampled (0 when the segment does
  /// not leave a vertex that ran it, or left it by a delta component). The
  /// distance densities along the segment are the same for both.
  float lightDirectedRatio(const PathState& s, const Point3f& c) const {
    if (!s.segmentFromVertex || !s.prevLightDirected || s.prev.delta || !(s.prev.bsdfPdf > 0.0f)) return 0.0f;
    return pdfPointDirection(s.prev.p, c, s.ray.d) / (s.prev.bsdfPdf * s.passProbability);
  }

  /// A free flight crossed the medium segment [0, tMax] of s.ray without
  /// scattering: light-directed vertices follow straight rays past
  /// homogeneous segments only (free flights' probability of crossing them
  /// is exact there), so a heterogeneous segment is the last they sample a
  /// vertex on and ends their reach; a homogeneous one multiplies the
  /// probability of getting this far (homogeneous.cpp: the average over
  /// channels of the transmittance).
  void passSegment(PathState& s, float tMax, Sampler& sampler) const {
    if (!s.segmentFromVertex) return;
    if (!s.medium->isHomogeneous()) {
      s.segmentFromVertex = false;
      return;
    }
    s.passProbability *= s.medium->transmittance(s.ray, tMax, sampler).average();
    s.crossedMedium = true;
  }

  /// Does the scattering vertex the path is at (depth s.depth, already
  /// counted) sample a light-directed vertex? Only toward a medium vertex
  /// that may still connect to a light.
  bool runsLightDirected(const Scene& scene, const PathState& s) const {
    return lightDirections_ && equiangular_ && s.depth + 1 != depth_.maxDepth && !lightDirectedBeforeWindow(scene, s);
  }

  /// Time gating: could nothing the light-directed vertices of the vertex
  /// the path is at find arrive in the window? Their medium vertices arrive
  /// in it by construction (equiangularToward) and so cannot when even the
  /// longest way through the scene's box to every point light arrives before
  /// it (longestDetour; delays aside); then the vertex runs none (a rule of
  /// the vertex alone, as the path's own strategies' weights assume:
  /// prevLightDirected), and a late window does not pay the rays of early
  /// vertices. Light before the window then loses their variance reduction.
  bool lightDirectedBeforeWindow(const Scene& scene, const PathState& s) const {
    if (!(s.gate.start > -Infinity) || s.lights.anywhere || !scene.bbox().valid()) return false;
    double eta = std::max(s.etaMax, s.surfaceEta);
    const BoundingBox3f& box = scene.bbox();
    // Every point of the box is within this of the vertex.
    double farthest = distance(s.vertex, (box.min + box.max) * 0.5f) + 0.5 * length(box.max - box.min);
    for (int k = 0; k < s.lights.count; ++k) {
      // Cheap bounds first: the detour is at least |x - c| and at most that plus twice `farthest`.
      double direct = distance(s.vertex, s.lights.points[k]);
      if (!(s.opl + eta * direct < s.gate.start)) return false;
      if (s.opl + eta * (direct + 2.0 * farthest) < s.gate.start) continue;
      if (!(s.opl + eta * longestDetour(s.vertex, box, s.lights.points[k]) < s.gate.start)) return false;
    }
    return true;
  }

  /// Time gating: the weight of a light connection of length `dist` from
  /// OPL `opl`. 1 unless its light surely arrives before the window (at most
  /// etaMax times its length; delays before `opl` counted); such a
  /// connection is made with probability before_window_rate and weighted by
  /// its inverse (Russian roulette: the steady image and _before keep their
  /// means, at more noise; the window's estimate cannot change, nothing
  /// left out lands in it), and 0 (not made) when the rate is 0
  /// (skip_before_window). Why: on a late window those shadow rays are most
  /// of the time spent (docs/BENCHMARKS.md, transient_path sampling (b)).
  float beforeWindowWeight(const PathState& s, double opl, float dist, Sampler& sampler) const {
    if (!timeGating_ || beforeWindowRate_ >= 1.0f || !std::isfinite(dist) ||
        !(opl + double(std::max(s.etaMax, s.surfaceEta)) * dist < s.gate.start))
      return 1.0f;
    if (!(beforeWindowRate_ > 0.0f) || !(sampler.next1D() < beforeWindowRate_)) return 0.0f;
    return 1.0f / beforeWindowRate_;
  }

  /// The light-directed next-event vertices (see the header): from the
  /// scattering vertex `ref` (a surface, or a medium point with zero normal)
  /// a direction w around a point light (transport/point_directions.h), then,
  /// along the straight ray in w through index-matched boundaries, one
  /// equiangular vertex per medium segment up to the first heterogeneous one,
  /// as the path's own segments get (lightDirectedVertex).
  template <typename ScatterFn>
  void nextEventLightDirected(const Scene& scene, const PathState& s, const SurfaceInteraction& ref, Sampler& sampler,
                              RadianceRecorder& recorder, ScatterFn&& scatter) const {
    float uPick = sampler.next1D(), uDistance = sampler.next1D();
    Point2f uDirection = sampler.next2D();
    LightDirected l;
    l.emitter = scene.pickEmitter(uPick);
    l.uPick = uPick;
    if (!l.emitter || !l.emitter->deltaPosition(l.lightPosition)) return;
    float pdf = 0.0f;
    Vec3f w = samplePointDirection(ref.p, l.lightPosition, uDirection, pdf);
    if (!(pdf > 0.0f)) return;
    l.lightPdf = pdfPointDirection(ref.p, l.lightPosition, w);  // the density the other strategies' weights use
    if (!(l.lightPdf > 0.0f)) return;
    Color3f f = scatter(w, l.vertexPdf);
    if (f.isBlack()) return;
    l.weight = s.throughput * f / l.lightPdf;
    const Medium* medium = mediumAfter(ref, w, s.medium);
    Ray ray = ref.spawnRay(w);
    Point3f start = ref.p;
    double opl = s.opl;
    for (int crossing = 0; crossing < MaxPassThrough; ++crossing) {
      SurfaceInteraction hit;
      bool hitSurface = scene.rayIntersect(ray, hit);
      float tMax = hitSurface ? hit.t : Infinity;
      if (medium) {
        GatedSegment gated = gatedSegment(s.gate, s.lights, ray, start, tMax, *medium, opl);
        lightDirectedVertex(scene, s, l, ray, tMax, *medium, opl, gated, crossing == 0 ? uDistance : sampler.next1D(),
                            sampler, recorder);
        // Past a heterogeneous segment the path's own free flights arrive
        // with a probability that has no closed form (passSegment): the
        // straight ray ends there, for both strategies.
        if (!medium->isHomogeneous()) return;
        Color3f tr = medium->transmittance(ray, tMax, sampler);
        l.weight *= tr;
        // The path's own free flights end within a truncated segment (sampleFreeFlight).
        l.passProbability *= gated.truncates(tMax) ? 0.0f : tr.average();
        l.crossedMedium = true;
      }
      if (!hitSurface || l.weight.isBlack()) return;
      opl += double(medium ? medium->eta() : s.surfaceEta) * distance(start, hit.p);
      if (opl >= recorder.horizon()) return;
      if (!isPassThrough(hit)) {
        lightDirectedSurface(scene, s, l, hit, medium, opl, sampler, recorder);
        return;
      }
      medium = mediumAfter(hit, ray.d, medium);
      start = hit.p;
      ray = hit.spawnRay(ray.d);
    }
  }

  /// What the light-directed vertices of one direction share.
  struct LightDirected {
    const Emitter* emitter = nullptr;
    Point3f lightPosition;
    float uPick = 0.0f;
    float lightPdf = 0.0f, vertexPdf = 0.0f;  // densities of the direction: light-directed, the vertex's own sampling
    Color3f weight;                           // throughput * f(w) / p_light(w) * transmittance of earlier segments
    float passProbability = 1.0f;             // free flights' probability of crossing the earlier segments
    bool crossedMedium = false;               // one of them was in a medium
  };

  /// One light-directed vertex: an equiangular distance t on the segment
  /// [0, tMax] of `ray` in `medium` (starting at OPL `startOpl`) and the
  /// connection from there to the light: records
  /// l.weight * sigma_s T(t) / p_eq(t) * phase * Le * T_light,
  /// MIS-weighted against the free-flight and equiangular vertices that the
  /// direction's own sampling would give on the same segment (densities
  /// vertexPdf * passProbability times p_ff(t) or p_eq(t)).
  void lightDirectedVertex(const Scene& scene, const PathState& s, const LightDirected& l, const Ray& ray, float tMax,
                           const Medium& medium, double startOpl, const GatedSegment& gated, float uDistance,
                           Sampler& sampler, RadianceRecorder& recorder) const {
    EquiangularSegment seg = equiangularToward(ray, tMax, medium, s.gate, startOpl, l.lightPosition);
    if (!seg.valid()) return;
    float pdf = 0.0f;
    float t = sampleEquiangular(seg, uDistance, pdf);
    if (!(pdf > 0.0f)) return;
    SurfaceInteraction x;  // a medium vertex: zero normal
    x.p = ray(t);
    x.n = Normal3f(0.0f);
    Color3f vertex = medium.scatteringCoefficient(x.p) * medium.transmittance(ray, t, sampler) / pdf;
    if (vertex.isBlack()) return;
    double opl = startOpl + double(medium.eta()) * t;
    const PhaseFunction& phase = medium.phase();
    if (phase.hasDelay()) opl += phase.sampleDelay(sampler.next1D());
    DirectionSample ds;
    Color3f Le = l.emitter->sampleDirection(x.p, Point2f(l.uPick, 0.5f), ds);
    if (!(ds.pdf > 0.0f) || Le.isBlack() || opl + ds.dist >= recorder.horizon()) return;
    Le = Le / scene.emitterPickProbability(l.emitter);
    Color3f fx(phase.eval(-ray.d, ds.d));
    if (fx.isBlack()) return;
    Connection c = connect(scene, x, ds.d, ds.p, ds.dist, &medium, s.surfaceEta, sampler);
    if (c.transmittance.isBlack()) return;
    // Densities of the three strategies for this vertex, divided by the common
    // p_eq(t) / t^2. In a heterogeneous medium the free-flight vertex takes
    // no distance an equiangular one can sample (freeFlightVertexWeight).
    float own = l.vertexPdf * l.passProbability;
    float weight = powerHeuristic(l.lightPdf, own, own * freeFlightPdf(gated, tMax, medium, t) / pdf);
    recorder.addPulsed(opl + c.opl, opl + c.opl, l.weight * vertex * fx * Le * c.transmittance * weight,
                       l.emitter->pulse());
  }

  /// The surface the light-directed ray ends on, as a scattering vertex that
  /// connects to the light: records l.weight * f * Le * T_light. Why: a
  /// surface close to a point light (the fog box's ceiling, 0.2 above it)
  /// receives ~1/r^2 and is reached only by phase- or BSDF-sampled directions,
  /// so its next-event estimates are rare and large (the late window's MSE,
  /// docs/BENCHMARKS.md); the light-directed direction (density ~ 1/sin of the
  /// angle to the light) passes the light and lands near that spot. Combined
  /// with the path's own direction by the power heuristic over the direction
  /// densities (Veach 1997, eq. 9.13), the own one times free flights'
  /// probability of crossing the media on the way (as lightDirectedVertex).
  /// Only where the ray crossed a medium (both strategies apply the same
  /// rule): without fog the fog box measured it efficiency-neutral (MSE 1.29x
  /// lower at 1.33x the CPU), and in surface-only scenes transient_path is
  /// held to path's cost per sample (docs/BENCHMARKS.md, target 1.1).
  void lightDirectedSurface(const Scene& scene, const PathState& s, const LightDirected& l,
                            const SurfaceInteraction& hit, const Medium* medium, double opl, Sampler& sampler,
                            RadianceRecorder& recorder) const {
    const BSDF* bsdf = hit.bsdf();
    if (!l.crossedMedium || !bsdf || !bsdf->hasSmooth()) return;
    if (bsdf->hasDelay()) opl += bsdf->sampleDelay(sampler.next1D());
    float beforeWindow = beforeWindowWeight(s, opl, distance(hit.p, l.lightPosition), sampler);
    if (!(beforeWindow > 0.0f)) return;
    DirectionSample ds;
    Color3f Le = l.emitter->sampleDirection(hit.p, Point2f(l.uPick, 0.5f), ds);
    if (!(ds.pdf > 0.0f) || Le.isBlack() || opl + ds.dist >= recorder.horizon()) return;
    Le = Le / scene.emitterPickProbability(l.emitter);
    Color3f f = bsdf->eval(hit, hit.toLocal(ds.d));
    if (f.isBlack()) return;
    Connection c = connect(scene, hit, ds.d, ds.p, ds.dist, mediumAfter(hit, ds.d, medium), s.surfaceEta, sampler);
    if (c.transmittance.isBlack()) return;
    float weight = powerHeuristic(l.lightPdf, l.vertexPdf * l.passProbability, 0.0f);
    recorder.addPulsed(opl + c.opl, opl + c.opl, l.weight * f * Le * c.transmittance * (weight * beforeWindow),
                       l.emitter->pulse());
  }

  /// Next-event estimation from a medium vertex whose distance along the
  /// current segment is sampled equiangularly toward a light at a point
  /// (Kulla and Fajardo 2012): records
  /// throughput * sigma_s T(t) / pdf(t) * phase * Le * T_light, MIS-weighted
  /// against the free-flight vertex's estimate (scatterInMedium), at the OPL
  /// of the whole path. Emitters not at a point are left to free flights.
  void nextEventEquiangular(const Scene& scene, const PathState& s, Sampler& sampler,
                            RadianceRecorder& recorder) const {
    float uPick = sampler.next1D(), uDistance = sampler.next1D();
    const Emitter* emitter = scene.pickEmitter(uPick);
    Point3f lightPosition;
    if (!emitter || !emitter->deltaPosition(lightPosition)) return;
    EquiangularSegment seg = equiangularToward(s, lightPosition);
    if (!seg.valid()) return;
    float pdf = 0.0f;
    float t = sampleEquiangular(seg, uDistance, pdf);
    if (!(pdf > 0.0f)) return;
    SurfaceInteraction ref;  // a medium vertex: zero normal
    ref.p = s.ray(t);
    ref.n = Normal3f(0.0f);
    Color3f vertex = s.medium->scatteringCoefficient(ref.p) * s.medium->transmittance(s.ray, t, sampler) / pdf;
    if (vertex.isBlack()) return;
    double opl = s.opl + (segmentCounts(observerTime_, s.cameraSegment) ? s.segmentOpl(ref.p) : 0.0);
    const PhaseFunction& phase = s.medium->phase();
    if (phase.hasDelay()) opl += phase.sampleDelay(sampler.next1D());
    DirectionSample ds;
    Color3f Le = emitter->sampleDirection(ref.p, Point2f(uPick, 0.5f), ds);
    if (!(ds.pdf > 0.0f) || Le.isBlack() || opl + ds.dist >= recorder.horizon()) return;
    Le = Le / scene.emitterPickProbability(emitter);
    Color3f f(phase.eval(-s.ray.d, ds.d));
    if (f.isBlack()) return;
    Connection c = connect(scene, ref, ds.d, ds.p, ds.dist, s.medium, s.surfaceEta, sampler);
    if (c.transmittance.isBlack()) return;
    // Heterogeneous: the distances it samples are its own against free
    // flights (freeFlightVertexWeight), shared only with the light-directed
    // vertex, whose distance density along the same segment is the same.
    float weight = powerHeuristic(pdf, freeFlightPdf(s, t), pdf * lightDirectedRatio(s, lightPosition));
    recorder.addPulsed(opl + c.opl, opl + c.opl, s.throughput * vertex * f * Le * c.transmittance * weight,
                       emitter->pulse());
  }

  /// MIS weight of the free-flight vertex at distance t on the current
  /// segment for its next-event estimate toward a point light at `c`, against
  /// the segment's equiangular vertex (and the light-directed one). In
  /// homogeneous media the power heuristic over their densities. A
  /// heterogeneous medium's free flights (tracking) have no closed-form
  /// density, so there the segment is split instead: the equiangular vertex
  /// takes every distance it can sample (its weight is 1) and the free-flight
  /// vertex the others (weight 1 where p_eq(t) = 0, else 0), a partition of
  /// unity (Veach 1997, sec. 9.2.2, the cutoff heuristic at cutoff 0), so the
  /// sum stays unbiased; the light-directed vertex samples the same distances
  /// as the equiangular one (the same segment's equiangular density) and
  /// shares them with it by the direction densities alone.
  float freeFlightVertexWeight(const PathState& s, const Point3f& c, float t) const {
    float equiangular = pdfEquiangular(equiangularToward(s, c), t);
    if (!s.medium->isHomogeneous()) return equiangular > 0.0f ? 0.0f : 1.0f;
    return powerHeuristic(freeFlightPdf(s, t), equiangular, equiangular * lightDirectedRatio(s, c));
  }

  bool scatterInMedium(const Scene& scene, PathState& s, const Point3f& p, float t, Sampler& sampler,
                       RadianceRecorder& recorder) const {
    if (!enterScatteringVertex(s)) return false;
    const PhaseFunction& phase = s.medium->phase();
    if (phase.hasDelay()) {
      s.opl += phase.sampleDelay(sampler.next1D());
      if (s.opl >= recorder.horizon() || pastGate(s)) return false;
    }
    Vec3f wi = -s.ray.d;
    SurfaceInteraction ref;  // a medium vertex: zero normal, so rays leave it without offset
    ref.p = p;
    ref.n = Normal3f(0.0f);
    nextEvent(
        scene, s, ref, sampler, recorder,
        [&](const Vec3f& wo, float& pdf) {
          pdf = phase.pdf(wi, wo);
          return Color3f(phase.eval(wi, wo));
        },
        t);
    bool lightDirected = runsLightDirected(scene, s);
    if (lightDirected)
      nextEventLightDirected(scene, s, ref, sampler, recorder, [&](const Vec3f& wo, float& pdf) {
        pdf = phase.pdf(wi, wo);
        return Color3f(phase.eval(wi, wo));
      });
    return continueSplit(scene, s, sampler, recorder, [&](PathState& c) {
      Vec3f wo;
      float pdf = 0.0f;
      float weight = phase.sample(wi, sampler.next2D(), wo, pdf);
      if (!(pdf > 0.0f) || !(weight > 0.0f)) return false;
      c.throughput *= weight;
      c.prev.p = p;
      c.prev.bsdfPdf = pdf;
      c.prev.delta = false;
      c.ray = Ray(p, wo);
      c.segmentFromVertex = true;
      c.prevLightDirected = lightDirected;
      c.passProbability = 1.0f;
      c.crossedMedium = false;
      return russianRoulette(c, sampler, recorder.timeGrid());
    });
  }

  bool scatterOnSurface(const Scene& scene, PathState& s, const SurfaceInteraction& si, Sampler& sampler,
                        RadianceRecorder& recorder) const {
    if (!enterScatteringVertex(s)) return false;
    const BSDF& bsdf = *si.bsdf();
    if (bsdf.hasDelay()) {  // time spent scattering here delays everything that leaves this vertex
      s.opl += bsdf.sampleDelay(sampler.next1D());
      if (s.opl >= recorder.horizon() || pastGate(s)) return false;
    }
    bool lightDirected = bsdf.hasSmooth() && runsLightDirected(scene, s);
    if (bsdf.hasSmooth()) {
      auto scatter = [&](const Vec3f& wo, float& pdf) {
        Vec3f local = si.toLocal(wo);
        pdf = bsdf.pdf(si, local);
        return bsdf.eval(si, local);
      };
      nextEvent(scene, s, si, sampler, recorder, scatter);
      if (lightDirected) nextEventLightDirected(scene, s, si, sampler, recorder, scatter);
    }
    return continueSplit(scene, s, sampler, recorder, [&](PathState& c) {
      BSDFSample bs;
      Color3f weight = bsdf.sample(si, sampler.next1D(), sampler.next2D(), bs);
      if (!(bs.pdf > 0.0f) || weight.isBlack()) return false;
      Vec3f wo = si.toWorld(bs.wo);
      c.throughput *= weight;
      c.etaScale *= bs.eta * bs.eta;
      c.leaveSurface(si, wo, bs.eta);
      c.prev.p = si.p;
      c.prev.bsdfPdf = bs.pdf;
      c.prev.delta = (bs.sampledFlags & BSDFFlags::Delta) != 0;
      c.segmentFromVertex = true;
      c.prevLightDirected = lightDirected;
      c.passProbability = 1.0f;
      c.crossedMedium = false;
      return russianRoulette(c, sampler, recorder.timeGrid());
    });
  }

  /// Leave a scattering vertex (its next-event estimates made): `continueFrom`
  /// samples the direction onward and applies the roulette. time_splitting
  /// first splits the path into n copies of 1/n its throughput when its
  /// throughput is n or more times the time level at its OPL (TimeLevels);
  /// each copy samples its own direction and is traced to its end here, the
  /// path itself continues. Splitting and roulette keep the estimate unbiased
  /// for any levels (docs/design/transient-path.md, "Splitting against time").
  template <typename ContinueFn>
  bool continueSplit(const Scene& scene, PathState& s, Sampler& sampler, RadianceRecorder& recorder,
                     ContinueFn&& continueFrom) const {
    if (!levels_.level.empty()) {
      const float ratio = relativeThroughput(s, recorder.timeGrid());
      const int n = TimeLevels::splitCount(ratio, s.splitProduct);
      if (n >= 2) {
        s.throughput = s.throughput / float(n);
        s.splitProduct *= n;
        for (int k = 1; k < n; ++k) {
          PathState copy = s;
          if (continueFrom(copy)) trace(scene, copy, sampler, recorder);
        }
      }
    }
    return continueFrom(s);
  }

  /// The throughput (refraction's radiance scaling removed, so paths inside
  /// glass are not killed unfairly) over the time level at the path's OPL
  /// (1 without time_splitting: Mitsuba's roulette).
  float relativeThroughput(const PathState& s, const TimeGrid& grid) const {
    return s.throughput.maxValue() * s.etaScale / levels_.at(grid, s.opl);
  }

  /// Russian roulette on the relative throughput. Survival is capped at
  /// RouletteCap, 0.99 as in mitransient's prbvolpath (Mitsuba's path uses
  /// 0.95): in media of albedo near 1 the cap is what ends paths, and only
  /// late bins see them (docs/design/transient-path.md).
  bool russianRoulette(PathState& s, Sampler& sampler, const TimeGrid& grid) const {
    if (s.depth < depth_.rrDepth) return true;
    float q = std::min(relativeThroughput(s, grid), RouletteCap);
    if (!(sampler.next1D() < q)) return false;
    s.throughput = s.throughput / q;
    return true;
  }

  static constexpr float RouletteCap = 0.99f;  // russianRoulette
  // time_splitting: the pilot's seed.
  static constexpr uint64_t PilotSeedSalt = 0x7069'6c6f'7421'5eedull;
  PathDepthSettings depth_;
  bool hideEmitters_;
  bool observerTime_;
  bool equiangular_;
  bool lightDirections_;
  bool timeGating_;
  bool timeSplitting_;
  TimeLevels levels_;  // time_splitting: set on the copy render() renders with
  float beforeWindowRate_;
  /// before_window_rate's default (docs/BENCHMARKS.md, transient_path sampling (b)).
  static constexpr float DefaultBeforeWindowRate = 0.125f;
  bool discardDirectLight_ = false;
};

}  // namespace femto

#if defined(FEMTO_TRANSIENT_PATH_AS_PRBVOLPATH)
namespace femto {
// mitransient's integrators derive from Mitsuba 3's ADIntegrator, whose max_depth defaults to 6.
class MitransientPrbVolpath final : public TransientPathIntegrator {
 public:
  explicit MitransientPrbVolpath(const Properties& props) : TransientPathIntegrator(props, {6}) {}
};
}  // namespace femto
FEMTO_EXPORT_PLUGIN(femto::MitransientPrbVolpath, Integrator, "transient_prbvolpath",
                    "mitransient's volumetric path tracer: transient_path with max_depth 6 by default")
#elif defined(FEMTO_TRANSIENT_PATH_AS_TRANSIENTPATH)
FEMTO_EXPORT_PLUGIN(femto::TransientPathIntegrator, Integrator, "transientpath",
                    "Mitsuba 2's transient path tracer: transient_path under its old name")
#else
FEMTO_EXPORT_PLUGIN(femto::TransientPathIntegrator, Integrator, "transient_path",
                    "Transient volumetric path tracer (contributions binned by optical path length)")
#endif
