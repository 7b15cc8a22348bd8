// `femto render scene.xml`: load, render with the scene's integrator, write
// the image, print a one-line summary.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include <tbb/global_control.h>

#include <femto/base/error.h>
#include <femto/core/duration.h>
#include <femto/core/log.h>
#include <femto/core/resources.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/xml/loader.h>

#include "arguments.h"
#include "command_options.h"
#include "commands.h"
#include "interrupt.h"
#include "mpi/render_processes.h"

namespace fs = std::filesystem;

namespace femto::cli {
namespace {

struct RenderSettings {
  std::string scene;
  std::string output;
  std::vector<std::string> defines;
  int threads = 0;
  uint64_t seed = 0;
  int sampleCount = 0;  // 0: the scene's
  int passes = 0;       // 0: the integrator's
  std::string timeLimit;   // "30s", "5m", "90": empty for none
  std::string timeClock = "wall";
  std::string resolution;
  std::string integratorFile;  // --integrator: empty for the scene's
  bool strict = false;
  bool noProgress = false;
  std::vector<std::string> pluginDirs;
  std::function<void()> applyPluginDirs;
};

/// `-o` or `<scene stem>.exr` in the current directory.
fs::path outputPath(const RenderSettings& settings) {
  if (!settings.output.empty()) return settings.output;
  return fs::path(settings.scene).stem().string() + ".exr";
}

/// The output must be writable before any work starts: a render that fails
/// only when it writes loses all of it. A missing folder is made, as the
/// writers always did (`make render` writes to out/). Messages name the path
/// as the user gave it.
void checkOutputWritable(const fs::path& output) {
  if (fs::is_directory(output))
    throw Error(str("-o \"", output.string(), "\" is a folder: give a file name, e.g. \"", (output / "image.exr").string(), "\""));
  requireWritableFolder(output.parent_path(), output, /*makeMissing=*/true);
}

LoadOptions loadOptions(const RenderSettings& settings) {
  LoadOptions options;
  options.defines = parseDefines(settings.defines);
  options.strict = settings.strict;
  if (!settings.resolution.empty()) options.resolution = parseResolution(settings.resolution);
  if (settings.sampleCount > 0) options.sampleCount = settings.sampleCount;
  if (!settings.integratorFile.empty()) options.integratorFile = settings.integratorFile;
  return options;
}

/// --time-limit and --time-clock into the render's options.
void applyTimeLimit(const RenderSettings& settings, RenderOptions& options) {
  options.passes = settings.passes;
  if (settings.timeLimit.empty()) return;
  try {
    options.timeLimit = parseDuration(settings.timeLimit);
  } catch (const Error& e) {
    throw UsageError(str("--time-limit: ", e.what()));
  }
  options.timeClock = settings.timeClock == "cpu" ? RenderClock::Cpu : RenderClock::Wall;
}

/// `seconds`: wall time of the whole job (every pass and every file written),
/// not only of the tile loops that stats.seconds sums. A render in passes
/// says how many, and under a time limit the command that renders the same
/// bits without one (scripts read both lines: tools/compare/render_runs.py).
void printSummary(const fs::path& output, const RenderStats& stats, double seconds, bool interrupted,
                  const RenderSettings& settings, int samplesPerPass) {
  std::cout << std::fixed << std::setprecision(3) << (stats.completed ? "rendered " : "stopped early, partial image ") << output.string() << " in "
            << seconds << " s (" << stats.samples << " samples)\n";
  if (stats.passes > 0 && (stats.passes > 1 || settings.passes > 0 || !settings.timeLimit.empty())) {
    std::cout << stats.passes << " passes of " << samplesPerPass << " spp (" << uint64_t(stats.passes) * uint64_t(samplesPerPass)
              << " spp), rendering " << stats.seconds << " s, " << stats.cpuSeconds << " s CPU";
    if (!settings.timeLimit.empty())
      std::cout << "; time limit " << settings.timeLimit << " (" << settings.timeClock << " clock) "
                << (stats.timeLimitReached ? "reached" : "not reached") << "; the same image without it: --passes "
                << stats.passes << " --spp " << samplesPerPass << " --seed " << settings.seed;
    std::cout << '\n';
  }
  if (stats.invalidSamples > 0)
    logWarn(stats.invalidSamples, " of ", stats.samples,
            " samples were NaN, infinite or negative and were left out of the image: the integrator has a bug");
  if (interrupted) std::cout << "interrupted by Ctrl-C\n";
}

int renderHere(const RenderSettings& settings, const RenderProcesses& processes) {
  settings.applyPluginDirs();
  // Parse every argument before the (possibly slow) scene load.
  LoadOptions load = loadOptions(settings);
  RenderOptions options;
  options.threads = settings.threads;
  options.seed = settings.seed;
  applyTimeLimit(settings, options);
  options.output = outputPath(settings);
  // Under mpirun only rank 0 writes and draws; the others render tiles for it.
  options.progress = !settings.noProgress && processes.writes();
  if (processes.writes()) checkOutputWritable(options.output);

  std::optional<tbb::global_control> threadLimit;
  if (settings.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism, size_t(settings.threads));

  std::shared_ptr<Scene> scene = loadScene(settings.scene, load);
  scene->sensor().film().checkOutputPath(options.output);
  const fs::path output = options.output;
  if (!processes.writes()) options.output.clear();
  InterruptGuard interrupt;
  options.cancel = &interrupt.cancelFlag();
  const auto start = std::chrono::steady_clock::now();
  RenderStats stats = scene->integrator().render(*scene, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!processes.writes()) return 0;
  printSummary(output, stats, seconds, interrupt.interrupted(), settings,
               int(scene->sensor().sampler().sampleCount()));
  // 128 + SIGINT tells scripts the image is partial.
  return interrupt.interrupted() ? 130 : 0;
}

int render(const RenderSettings& settings) {
  RenderProcesses processes;
  if (processes.count() == 1) return renderHere(settings, processes);
  // The ranks would have to agree, pass by pass, on the time left: a pass
  // count gives the same bits on any number of ranks instead.
  if (!settings.timeLimit.empty()) {
    if (processes.writes())
      std::cerr << "error: --time-limit is not supported under mpirun (" << processes.count()
                << " ranks): give the number of passes instead (--passes N; a time-limited render on one process "
                   "prints the count it reached)\n";
    return 2;
  }
  // One rank failing leaves the others waiting for it: end them all.
  try {
    return renderHere(settings, processes);
  } catch (const std::exception& e) {
    processes.abortJob(e.what());
  }
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto s = std::make_shared<RenderSettings>();
  CLI::App* command = app.add_subcommand("render", "Render a Mitsuba XML scene to an OpenEXR image");
  command->add_option("scene", s->scene, "Scene file (Mitsuba 0.6 or 3 XML)")->required()->check(CLI::ExistingFile);
  addOutputOption(*command, s->output, "Output image (default: <scene name>.exr in the current directory)");
  command->add_option("-D,--define", s->defines, "Set a scene <default> or $name: -D spp=64 (repeatable)")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  addCountOption(*command, "-t,--threads", s->threads, "Worker threads (default: all cores)");
  command->add_option("--seed", s->seed, "Base random seed; the image depends only on scene and seed")->type_name("N");
  addCountOption(*command, "--spp", s->sampleCount, "Samples per pixel (overrides the scene's sampler); per pass with --passes or --time-limit");
  addCountOption(*command, "--passes", s->passes,
                 "Render N passes of the sampler's spp with their own seeds and average them (default: the integrator's; "
                 "with --time-limit: the most)");
  command->add_option("--time-limit", s->timeLimit,
                      "Render whole passes until the next would pass this time (30s, 5m, 90 = seconds); the output "
                      "and its sidecar say how many")
      ->type_name("DURATION");
  command->add_option("--time-clock", s->timeClock, "Clock of --time-limit: wall (default) or cpu (all threads' CPU time)")
      ->check(CLI::IsMember({"wall", "cpu"}))
      ->type_name("wall|cpu");
  command->add_option("--resolution", s->resolution, "Film size (overrides the scene's film)")->type_name("WxH");
  command->add_option("--integrator", s->integratorFile,
                      "Render with the <integrator> of this XML file instead of the scene's")
      ->type_name("FILE.xml")
      ->check(CLI::ExistingFile);
  command->add_flag("--strict", s->strict, "Treat unused scene parameters as errors");
  command->add_flag("--no-progress", s->noProgress, "Do not draw the progress bar");
  s->applyPluginDirs = addPluginDirOption(*command, s->pluginDirs);
  return [s] { return render(*s); };
}

}  // namespace femto::cli
