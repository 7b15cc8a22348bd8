// The transient render driver: a transient integrator's passes over the
// whole film, streamed tile by tile into a transient film (or summed into a
// steady image), with the film's time machinery.
#include <femto/film/transient_render.h>

#include <tbb/task_arena.h>

#include <algorithm>
#include <fstream>
#include <limits>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/core/progress.h>
#include <femto/film/phasor_film.h>
#include <femto/film/transient_film.h>
#include <femto/film/transient_output.h>
#include <femto/film/transient_tile.h>
#include <femto/loop/pass_schedule.h>
#include <femto/loop/render_loop.h>
#include <femto/film/npy_volume.h>
#include <femto/image/write_atomically.inl>
#include <femto/render/emitter.h>
#include <femto/render/nlos_sensor.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/render/sampler.h>

namespace femto {
namespace {

/// Refuse, before rendering, pulses the film cannot deposit exactly.
void checkEmitterPulses(const Scene& scene, const TransientFilm& film) {
  if (film.timeFilter().type() == TimeFilter::Type::Box) return;
  for (const auto& emitter : scene.emitters())
    if (emitter->pulse().type() == EmissionPulse::Type::Gaussian)
      throw Error(str(emitter->toString(), (emitter->id().empty() ? "" : " (id \"" + emitter->id() + "\")"),
                      " has a gaussian pulse, which needs the transient film's time_filter \"box\", not \"",
                      film.timeFilter().name(), "\": the pulse already smooths in time (widen it instead)"));
}

RenderStats renderTransient(const Scene& scene, const TransientFilm& film, const RenderOptions& options, int passes,
                            const TransientPassFunction& passIntegrator) {
  checkEmitterPulses(scene, film);
  TransientOutput output(film, options.output);
  PassSchedule schedule(options, passes);
  const double cpuStart = clockSeconds(RenderClock::Cpu);
  // One bar for the whole job: every pass, one unit per pixel, then the
  // frames, counted as one more pass (they read the whole volume back).
  const uint64_t pixels = uint64_t(film.cropSize().x) * uint64_t(film.cropSize().y);
  const uint64_t frameUnits = output.writesFrames() ? pixels : 0;
  ProgressReporter progress("Rendering", pixels * uint64_t(schedule.expectedPasses()) + frameUnits, options.progress,
                            options.onProgress);
  RenderStats stats;
  // A near-clip time origin (mitransient's films) moves each camera ray's
  // horizon later by its near-clip OPL: integrators tracing light (photon
  // passes) get the largest.
  const double originBound = film.nearClipOrigin() ? largestNearClipOrigin(scene) : 0.0;
  for (int pass = 0; schedule.startPass(pass); ++pass) {
    progress.setTotal(pixels * uint64_t(schedule.expectedPasses()) + frameUnits);
    std::shared_ptr<const TransientIntegrator> integrator =
        passIntegrator(pass, pulsedHorizon(film.timeDeposit(), scene) + originBound);
    TransientRenderContext context{scene, *integrator, film.timeDeposit(),
                                   film.nearClipOrigin() && integrator->countsCameraSegment()};
    auto makeTile = [&](const Point2i& offset, const Point2i& size) -> std::unique_ptr<TileAccumulator> {
      return std::make_unique<TransientTile>(offset, size, context);
    };
    auto consume = [&](TileAccumulator& tile) { output.consume(static_cast<TransientTile&>(tile), pass); };
    RenderOptions passOptions = options;
    passOptions.seed = passSeed(options.seed, pass);
    accumulatePassStats(stats, renderTileStream(scene, passOptions, makeTile, consume,
                                                TransientTile::bytesPerPixel(film.timeGrid().bins), &progress,
                                                output.storesTilesAlone()));
    output.endPass(pass);
    if (!stats.completed) break;  // a cancelled pass is partial: not counted
    ++stats.passes;
  }
  stats.timeLimitReached = schedule.limitReached();
  stats.cpuSeconds = clockSeconds(RenderClock::Cpu) - cpuStart;
  // The frames' share of the bar follows the passes actually rendered.
  const uint64_t passUnits = pixels * uint64_t(std::max(stats.passes, 1));
  progress.setTotal(passUnits + frameUnits);
  uint64_t framesCounted = 0;
  auto onFrames = [&](int done, int total) {
    const uint64_t units = frameUnits * uint64_t(done) / uint64_t(std::max(total, 1));
    progress.update(units - framesCounted);
    framesCounted = units;
  };
  RenderRecord record{stats.passes,
                      int(scene.sensor().sampler().sampleCount()),
                      options.seed,
                      options.timeLimit,
                      options.timeLimit > 0.0 ? clockName(options.timeClock) : "",
                      stats.timeLimitReached};
  output.setSidecarExtra(describeNlosCapture(scene, film, output.volumePath()));
  // Frames are written in parallel: with the thread count the user asked for.
  if (options.threads > 0) {
    tbb::task_arena arena(options.threads);
    auto finish = [&] { output.finish(onFrames, &record); };
    executeInArena(arena, finish);
  } else
    output.finish(onFrames, &record);
  progress.finish();
  return stats;
}

}  // namespace

/// An NLOS capture's geometry beside its volume, so a reconstruction needs
/// only the capture (tools/nlos/reconstruct.py): sidecar fields and
/// <stem>_wall.npy, the watched point of every pixel (height, width, xyz).
std::vector<std::pair<std::string, std::string>> describeNlosCapture(const Scene& scene, const Film& film,
                                                                   const std::filesystem::path& volume) {
  const auto* nlos = dynamic_cast<const NlosSensor*>(&scene.sensor());
  if (!nlos || volume.empty()) return {};
  auto point = [](const Point3f& p) { return str("[", double(p.x), ", ", double(p.y), ", ", double(p.z), "]"); };
  const Point2i crop = film.cropSize(), offset = film.cropOffset();
  std::vector<std::pair<std::string, std::string>> extra = {
      {"nlos_confocal", nlos->confocal() ? "true" : "false"},
      {"nlos_legs", nlos->accountsFirstAndLastBounces() ? "\"kept\"" : "\"removed\""},
      {"nlos_sensor_origin", point(nlos->sensorOrigin())}};
  if (std::optional<Point3f> origin = nlos->laserOrigin()) extra.push_back({"nlos_laser_origin", point(*origin)});
  if (!nlos->confocal()) extra.push_back({"nlos_laser_target", point(nlos->laserTarget(nlos->watchedPoint(0, 0)))});
  std::filesystem::path wall = volume.parent_path() / (volume.stem().string() + "_wall.npy");
  extra.push_back({"nlos_wall_points", str("\"", wall.filename().string(), "\"")});
  writeAtomically(wall, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    const std::vector<char> header = npyHeader({crop.y, crop.x, 3});
    out.write(header.data(), std::streamsize(header.size()));
    for (int j = 0; j < crop.y; ++j)
      for (int i = 0; i < crop.x; ++i) {
        const Point3f p = nlos->watchedPoint(offset.x + i, offset.y + j);
        const float xyz[3] = {p.x, p.y, p.z};
        out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
      }
    if (!out) throw Error(str("cannot write \"", tmp.string(), "\""));
  });
  return extra;
}

RenderStats renderTransientPasses(const Scene& scene, const RenderOptions& options, int passes,
                                  const TransientPassFunction& passIntegrator) {
  if (auto* phasor = dynamic_cast<const PhasorFilm*>(&scene.sensor().film()))
    return renderPhasor(scene, *phasor, options, passes, passIntegrator);
  if (auto* film = dynamic_cast<const TransientFilm*>(&scene.sensor().film()))
    return renderTransient(scene, *film, options, passes, passIntegrator);
  return renderSteadyPasses(scene, options, passes, [&](int pass) -> CameraRadianceFunction {
    std::shared_ptr<const TransientIntegrator> integrator =
        passIntegrator(pass, std::numeric_limits<double>::infinity());
    return [&scene, integrator](const Ray& ray, Sampler& sampler) {
      return integrator->steadyRadiance(scene, ray, sampler);
    };
  });
}

RenderStats TransientIntegrator::render(const Scene& scene, const RenderOptions& options) const {
  // Not owned: the pass function hands out this integrator itself.
  std::shared_ptr<const TransientIntegrator> self(std::shared_ptr<void>(), this);
  return renderTransientPasses(scene, options, 1, [&](int, double) { return self; });
}

}  // namespace femto
