// transient_beams: progressive transient photon beams (Marco, Jarosz,
// Gutierrez, Jarabo 2017, "Transient Photon Beams"; progressive form after
// Jarosz et al. 2011, "Progressive Photon Beams"). The orchestrator: it owns
// the passes; each pass traces fresh photons (photon_tracer.h), builds a beam
// map and a surface photon map (beam_map.h, surface_photon_map.h), renders the
// whole film with them (camera_tracer.h: beams in media, next-event estimation
// plus surface photons on surfaces) and is averaged into the film with equal
// weight (renderTransientPasses, render/transient_integrator.h); its maps are
// freed before the next pass, so memory is that of one pass. Kernel radii
// shrink per pass (beam_settings.h). Time is optical path length: photons and
// camera paths add eta times every segment (and phase-function delays), and a
// ray x beam pair covers a continuous OPL interval, deposited exactly on the
// film's bins. Transport split and estimators: docs/design/photon-beams.md.
//
// Determinism: pass i's camera samples use the render loop's per-pixel seeds
// from passSeed(seed, i); its photons use streams seeded by (that seed,
// photon index); maps are built in photon order. The output depends on the
// seed, never on the thread count.
//
// | name           | type    | default        | meaning                                                   | unit   |
// |----------------|---------|----------------|-----------------------------------------------------------|--------|
// | passes         | integer | 1              | progressive passes averaged into the film                 | -      |
// | photon_count   | integer | 100000         | photons per pass (all leave surface photons; only the     | -      |
// |                |         |                | beam photons are traced when no surface stores photons)   |        |
// | beam_photon_count | integer | 10000       | how many of them (the first) leave beams; 0: all; absent: | -      |
// |                |         |                | more when the derived radius is below the density radius  |        |
// | gather_fraction | float  | derived        | probability that a camera segment gathers beams, its      | -      |
// |                |         |                | estimates weighted by 1/it (Russian roulette; the sample's|        |
// |                |         |                | stratum decides: that share of a pixel's samples gather); |        |
// |                |         |                | 0 or absent: 1 in pass 0, then from pass 0's pilot's      |        |
// |                |         |                | costs (beam_settings.h, GatherCosts)                      |        |
// | surface_gather_fraction | float | derived | probability that a camera sample gathers surface      | -      |
// |                |         |                | photons, weighted by 1/it (the sample's stratum decides); |        |
// |                |         |                | 0 or absent: 2 / (spp per pass) within [1/8, 1], two      |        |
// |                |         |                | gathers a pixel per pass                                  |        |
// | gather_roulette | float  | 0.05           | camera transmittance at which a segment's gather starts   | -      |
// |                |         |                | an unbiased Russian roulette along it (homogeneous media; |        |
// |                |         |                | beam_roulette.h); 0: gathers reach the segment's end      |        |
// | radius         | float   | derived        | beam kernel radius of the first pass; 0 or absent: the    | scene  |
// |                |         |                | smallest of ~300 pass-0 beams per camera segment, a 4-bin |        |
// |                |         |                | OPL footprint (oblique pairs too), 0.4 % boundary loss    |        |
// |                |         |                | (beams: past their extensions; radius_rule.h), 0.1 % leak |        |
// |                |         |                | near point lights (light_leak.h)                          |        |
// | surface_radius | float   | derived        | surface photon kernel radius of the first pass; 0 or      | scene  |
// |                |         |                | absent: 64 nearest pass-0 photons, at most 2 pixels       |        |
// |                |         |                | (surface_radius_rule.h); 0.01 diagonal without probes     |        |
// | surface_time_width | float | 4 bins       | width of the surface photons' causal time kernel in the   | OPL    |
// |                |         |                | first pass (each deposits over [t, t + w] after its       |        |
// |                |         |                | arrival t); absent: 4 film bins (the beams' footprint);   |        |
// |                |         |                | 0: at the instant t                                       |        |
// | alpha          | float   | 0.9            | radius reduction: r_{i+1} = r_i (i+alpha)/(i+1) (beams),  | -      |
// |                |         |                | r^2 likewise (surfaces; r^2 and w each by the root of the |        |
// |                |         |                | factor with the time kernel)                              |        |
// | max_depth      | integer | -1             | longest camera + photon path in segments (-1: no limit)   | -      |
// | rr_depth       | integer | 5              | photon segments before Russian roulette                   | -      |
// | store          | string  | "all"          | beams stored: "all" orders, or "single" scattering only   | -      |
// | volume_estimator | string | "beams"       | media: "beams" (ray x beam 1D) or "points" (photon points | -      |
// |                |         |                | at scattering vertices, beam radiance estimate, 2D kernel:|        |
// |                |         |                | radius, alpha and beam_photon_count then apply to points) |        |
// | observer_time  | boolean | true           | include the camera segment in the OPL                     | -      |
// | time_splitting | boolean | true           | transient films, from pass 1 on: roulette and split       | -      |
// |                |         |                | photons against the film's time profile (a pilot of pass  |        |
// |                |         |                | 0's camera samples), so late light gets as many beams as  |        |
// |                |         |                | early light (false: roulette on the power alone)          |        |
// | stratified_photons | boolean | true       | the directions photons leave the emitters in are          | -      |
// |                |         |                | stratified over each pass (one per cell of a k x k grid,  |        |
// |                |         |                | jittered; beam photons apart), so they spread evenly, at  |        |
// |                |         |                | most the variance of independent draws (false: those)     |        |
// | time_gating    | boolean | true           | transient films: the camera side skips estimates landing  | -      |
// |                |         |                | wholly before the window (the map skips such beam pieces) |        |
// |                |         |                | but for before_window_rate of them, weighted by its       |        |
// |                |         |                | inverse (the steady and _before images stay unbiased)     |        |
// | before_window_rate | float | 0.125        | that share (0: skip them all; steady and _before then     | -      |
// |                |         |                | lack that light)                                          |        |
// | hide_emitters  | boolean | false          | emitters seen directly appear black                       | -      |
// ("diagonal": of the scene's bounding box.) At the end of a render one log
// line gives the work done (beams, camera segments, ray x beam tests and pair
// hits, and per second) and the time of each phase; the benchmarks read it.
#include <algorithm>
#include <string>

#include <tbb/task_arena.h>

#include <femto/base/thread_edges.h>
#include <femto/core/log.h>
#include <femto/core/resources.h>
#include <femto/core/plugin.h>
#include <femto/film/transient_film.h>
#include <femto/film/transient_render.h>
#include <femto/film/transient_tile.h>
#include <femto/loop/render_loop.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/transient_integrator.h>
#include <femto/time/time_levels.h>
#include <transient_beams/beam_pass.h>
#include <transient_beams/beam_settings.h>
#include <transient_beams/boundary_coverage.h>
#include <transient_beams/light_leak.h>
#include <transient_beams/radius_probe.h>
#include <transient_beams/surface_radius_rule.h>

namespace femto {
namespace {

/// The film's time axis (bins == 0 for steady films): the derived beam
/// radius keeps a pair's OPL footprint within a fraction of its bins.
TimeGrid filmTimeGrid(const Scene& scene) {
  const auto* film = dynamic_cast<const TransientFilm*>(&scene.sensor().film());
  return film ? film->timeGrid() : TimeGrid{};
}

/// Mixed into a pass's seed for its photons, so they draw from other streams than its pixels.
constexpr uint64_t PhotonSeedSalt = 0x70686f746f6e73ULL;  // "photons"

/// Work and time summed over the passes of one render: the statistics line
/// logged at the end ("transient_beams: ..."), which the benchmarks read
/// (ray x beam queries per second, time against beam count).
struct PassTotals {
  int passes = 0;
  uint64_t beams = 0, surfacePhotons = 0, photons = 0;
  uint64_t pieces = 0;      // beam map pieces (beam_map.h): how finely the beams were cut for tight boxes
  double beamLength = 0.0;  // summed beam length (after the roulette, beam_roulette.h)
  double traceSeconds = 0.0, buildSeconds = 0.0;
  beams::CameraStatistics camera;

  void add(const beams::BeamPass& pass) {
    ++passes;
    beams += pass.beamMap().beams().size();
    pieces += pass.beamMap().pieceCount();
    for (const beams::Beam& b : pass.beamMap().beams()) beamLength += b.length;
    surfacePhotons += pass.photonMap().size();
    photons += pass.tracedPhotons();
    traceSeconds += pass.traceSeconds();
    buildSeconds += pass.buildSeconds();
    camera += pass.cameraStatistics();
  }

  /// `seconds`: the whole render; the camera passes took what tracing and
  /// building did not. Rates are per wall second of the camera passes (all
  /// threads together).
  std::string summary(double seconds) const {
    const double cameraSeconds = std::max(seconds - traceSeconds - buildSeconds, 1e-9);
    const double rays = double(std::max<uint64_t>(camera.cameraRays, 1));
    const double segments = double(std::max<uint64_t>(camera.segments, 1));
    const double beamCount = double(std::max<uint64_t>(beams, 1));
    return str("transient_beams: ", passes, " passes, ", photons, " photons, ", beams, " beams, ", surfacePhotons,
               " surface photons; beams: mean length ", beamLength / beamCount, ", ", double(pieces) / beamCount,
               " map pieces each; time: photons ", traceSeconds, " s, maps ", buildSeconds, " s, camera ",
               cameraSeconds, " s; ", camera.cameraRays, " camera rays, ", camera.segments, " beam queries (",
               double(camera.candidates) / segments, " candidates and ", double(camera.pairHits) / segments,
               " pair hits each), ", double(camera.piecesCrossed) / segments, " map piece boxes crossed per query, ",
               camera.candidates, " ray x beam tests, ", camera.pairHits, " pair hits, ",
               double(camera.candidates) / cameraSeconds, " ray x beam tests/s, ",
               double(camera.pairHits) / cameraSeconds, " pair hits/s, ", double(camera.surfacePhotons) / rays,
               " surface photons per camera ray");
  }
};
}  // namespace

class TransientBeamsIntegrator final : public TransientIntegrator {
 public:
  explicit TransientBeamsIntegrator(const Properties& props) : settings_(beams::BeamSettings::parse(props)) {}

  /// transient_beams renders in passes (render()): a camera sample needs a
  /// pass's photon maps, so it cannot be nested in another integrator.
  void sample(const Scene&, const Ray&, Sampler&, RadianceRecorder&) const override {
    throw Error(settings_.location,
                "transient_beams renders whole passes (photon maps first, then the film) and "
                "cannot be sampled one camera ray at a time (e.g. nested in another integrator)");
  }

  RenderStats render(const Scene& scene, const RenderOptions& options) const override {
    // The beam radius, unless given, is derived from pass 0's beams and then
    // shrinks per pass like a given one (beam_settings.h).
    beams::BeamSettings settings =
        settings_.resolved(scene.bbox()).withSurfaceGatherFor(scene.sensor().sampler().sampleCount());
    PassTotals totals;
    // The pass just rendered: its counters are read before the next pass is
    // built (and its maps freed then, so memory stays that of one pass).
    std::shared_ptr<const beams::BeamPass> previous;
    auto collect = [&] {
      if (previous) totals.add(*previous);
      previous.reset();
    };
    RenderStats stats = renderTransientPasses(scene, options, settings.passes, [&](int pass, double horizon) {
      collect();
      const uint64_t seed = mixSeed(passSeed(options.seed, pass), PhotonSeedSalt);
      if (pass == 0) requirePassMemory(scene, settings, seed, horizon);
      auto trace = [&] {
        beams::PhotonPass traced = beams::tracePhotonPass(scene, settings, seed, horizon);
        if (pass == 0 && !(settings.radius > 0.0f)) {
          beams::DerivedRadius derived;
          const auto probes = beams::probeSegments(scene, horizon, settings.observerTime);
          const beams::SceneCoverage coverage{
              scene, beams::probeSegments(scene, horizon, settings.observerTime, beams::CoverageProbeGrid)};
          const double light = beams::lightBoundRadius(scene, traced.beams, probes,
                                                       beams::edgeProbeSegments(scene, horizon, settings.observerTime));
          settings = settings.withBeamRadiusFrom(traced.beams, probes, filmTimeGrid(scene), scene.bbox(), &derived,
                                                 light, &coverage);
          // A radius the film or the boundary made small gets more beams
          // (unless the scene gave their number): pass 0 is traced again.
          const beams::BeamSettings more = settings.withBeamsForRadius(derived);
          if (more.beamPhotons() != settings.beamPhotons()) {
            settings = more;
            traced = beams::tracePhotonPass(scene, settings, seed, horizon);
            // The boundary loss is counted again on the new beams: counted
            // on few beams' pairs it was noise where the radius is small
            // (random media seed 36, 10000 beam photons: 0.009-0.035
            // between photon seeds).
            const beams::DerivedRadius sized = derived;
            settings.radius = 0.0f;
            settings = settings.withBeamRadiusFrom(traced.beams, probes, filmTimeGrid(scene), scene.bbox(), &derived,
                                                   sized.light, &coverage, &sized);
          }
          logInfo("transient_beams: derived beam radius ", derived.radius, " (density ", derived.density, ", time ",
                  derived.time, ", boundary ", derived.boundary, ", light ", derived.light, "), ",
                  settings.beamPhotons(), " beam photons per pass");
        }
        // The surface radius, unless given, from pass 0's surface photons
        // and the film's pixels (surface_radius_rule.h); the scene's
        // default (resolved()) caps the photon search at 4 times it and
        // stays when no probe sees a surface.
        if (pass == 0 && !(settings_.surfaceRadius > 0.0f)) {
          const beams::DerivedSurfaceRadius surface =
              beams::deriveSurfaceRadius(scene, traced.surfacePhotons, 4.0 * double(settings.surfaceRadius));
          if (surface.radius > 0.0) settings.surfaceRadius = float(surface.radius);
          settings.surfaceRadiusFinal = true;
          logInfo("transient_beams: surface radius ", settings.surfaceRadius, " (density ", surface.density,
                  ", pixels ", surface.pixels, ")");
        }
        // The surface time kernel's width, unless given: the beams' time footprint in the film's bins.
        if (pass == 0 && settings.surfaceTimeWidth < 0.0f) {
          settings = settings.withSurfaceTimeWidthFor(filmTimeGrid(scene));
          logInfo("transient_beams: surface time width ", settings.surfaceTimeWidth, " (OPL)");
        }
        previous = std::make_shared<const beams::BeamPass>(settings, pass, std::move(traced), &scene, horizon);
        if (pass == 0 && settings.passes > 1) {
          settings.timeLevels = timeLevels(scene, *previous, options);
          // The beam gather fraction, unless given, from the pilot's work
          // (beam_settings.h, GatherCosts): pass 0 gathers at every segment.
          if (settings.timeLevels && settings.gatherFraction < 0.0f) {
            settings.gatherFraction = float(gatherCosts(scene, *previous).fraction());
            logInfo("transient_beams: gather fraction ", settings.gatherFraction, " from pass 1 on");
          }
        }
      };
      // Photons are traced with the thread count the user asked for.
      if (options.threads > 0) {
        tbb::task_arena arena(options.threads);
        executeInArena(arena, trace);
      } else
        trace();
      if (pass == 0) logInfo("transient_beams: pass 0: ", previous->toString());
      return std::static_pointer_cast<const TransientIntegrator>(previous);
    });
    collect();
    // The render time covers the photon passes too (tracing and map
    // building happen outside the render loop's clock), so that equal-time
    // comparisons with other integrators are fair (docs/compare.md).
    stats.seconds += totals.traceSeconds + totals.buildSeconds;
    logInfo(totals.summary(stats.seconds));
    return stats;
  }

  /// Resources before any work: the first photons of pass 0 (at most
  /// 4096, traced again in the pass) give the beams and surface photons per
  /// photon; a pass's maps (held while its camera samples render, the
  /// photons' blocks copied once into them, the map's sorted copies and BVH
  /// pieces on top) must fit in the available memory. time_splitting's
  /// passes hold more (BeamMap at most 16x the split photons'): the estimate
  /// is pass 0's, announced in the log with the photon counts.
  void requirePassMemory(const Scene& scene, const beams::BeamSettings& settings, uint64_t seed,
                         double horizon) const {
    const uint64_t total = uint64_t(settings.photonCount);
    const uint64_t sample = std::min<uint64_t>(total, 4096);
    if (sample == 0) return;
    beams::PhotonTracer tracer(scene, settings, horizon);
    std::vector<beams::Beam> beamList;
    std::vector<beams::SurfacePhoton> photons;
    uint64_t beamPhotons = 0;
    for (uint64_t i = 0; i < sample; ++i) {
      const bool store = i < uint64_t(settings.beamPhotons());
      beamPhotons += store;
      tracer.trace(seed, i, beamList, photons, store);
    }
    const double perPhoton = double(photons.size()) / double(sample);
    const double perBeamPhoton = beamPhotons > 0 ? double(beamList.size()) / double(beamPhotons) : 0.0;
    const double surfaceBytes = double(total) * perPhoton * (2.0 * sizeof(beams::SurfacePhoton) + 36.0);
    const double beamBytes = double(settings.beamPhotons()) * perBeamPhoton * (2.0 * sizeof(beams::Beam) + 16.0 * 64.0);
    const std::string what =
        str("transient_beams: one pass's photon maps (", total, " photons, ", settings.beamPhotons(), " leaving beams)");
    try {
      requireMemory(surfaceBytes + beamBytes, what, "lower photon_count (or beam_photon_count) and raise passes");
    } catch (const Error& e) {
      throw Error(settings.location, e.what());  // the <integrator> element's file and line
    }
    logInfo(what, ": about ", formatBytes(surfaceBytes + beamBytes), " (estimated from the first ", sample,
            " photons)");
  }

  /// What a gather and the rest of a camera sample cost, read off the first
  /// pass's pilot (its camera statistics before the pass renders: the same
  /// on every rank) and its photons and maps.
  static beams::GatherCosts gatherCosts(const Scene& scene, const beams::BeamPass& first) {
    const beams::CameraStatistics c = first.cameraStatistics();
    beams::GatherCosts g;
    if (c.cameraRays == 0) return g;
    const double rays = double(c.cameraRays), gathers = double(std::max<uint64_t>(c.segments, 1));
    const Film& film = scene.sensor().film();
    const double spp = double(std::max<uint32_t>(scene.sensor().sampler().sampleCount(), 1));
    const double samples = double(film.cropSize().x) * double(film.cropSize().y) * spp;
    g.gathersPerSample = double(c.segments) / rays;
    g.boxes = double(c.piecesCrossed) / gathers;
    g.candidates = double(c.candidates) / gathers;
    g.pairs = double(c.pairHits) / gathers;
    g.surfaceQueries = double(c.surfaceQueries) / rays;
    g.surfacePhotons = double(c.surfacePhotons) / rays;
    g.photonsPerSample = double(first.tracedPhotons()) / samples;
    g.piecesPerSample = double(first.beamMap().pieceCount()) / samples;
    g.storedPerSample = double(first.photonMap().size()) / samples;
    g.samplesPerPixel = spp;
    return g;
  }

  /// time_splitting: the film's time profile from a pilot of pass 0's camera
  /// samples (pilotTimeProfile; a quarter of a pass's, 256 to 4096), as
  /// transient_path reads its own; the photons of passes 1 on are rouletted
  /// and split against it (photon_tracer.h). Null without a transient film.
  std::shared_ptr<const TimeLevels> timeLevels(const Scene& scene, const beams::BeamPass& first,
                                               const RenderOptions& options) const {
    const auto* film = dynamic_cast<const TransientFilm*>(&scene.sensor().film());
    if (!settings_.timeSplitting || !film) return nullptr;
    auto levels = std::make_shared<TimeLevels>(
        pilotTimeLevels(scene, *film, first, mixSeed(options.seed, PilotSeedSalt), options.threads));
    if (levels->level.empty()) return nullptr;
    return levels;
  }

  std::string toString() const override {
    return str("TransientBeamsIntegrator[passes=", settings_.passes, ", photon_count=", settings_.photonCount,
               ", radius=", settings_.radius, ", surface_radius=", settings_.surfaceRadius,
               ", surface_time_width=", settings_.surfaceTimeWidth, ", alpha=", settings_.alpha,
               ", max_depth=", settings_.maxDepth,
               ", store=", settings_.store == beams::BeamStore::All ? "all" : "single",
               ", volume_estimator=", settings_.volumeEstimator == beams::VolumeEstimator::Points ? "points" : "beams",
               ", observer_time=", settings_.observerTime ? "true" : "false", "]");
  }

 private:
  beams::BeamSettings settings_;
  static constexpr uint64_t PilotSeedSalt = 0x6265'616d'7069'6c6full;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::TransientBeamsIntegrator, Integrator, "transient_beams",
                    "Progressive transient photon beams (media by ray x beam estimates, surfaces by NEE + photons)")
