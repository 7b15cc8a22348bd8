// `femto render scene.xml`: load, render with the scene's integrator, write
// the image, print a one-line summary. Several scenes (`femto render a.xml
// b.xml`, or --scene-list) render one after another into a folder; under
// mpirun with more scenes than ranks each rank renders whole scenes of its
// own. --resume skips scenes whose outputs a finished render recorded.

#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

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
  std::vector<std::string> scenes;
  std::string sceneList;  // --scene-list: a file naming scenes, one per line
  bool resume = false;
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

/// One scene: `-o` or `<scene stem>.exr` in the current directory. Several:
/// `<scene stem>.exr` in the folder `-o` names (default: the current one).
fs::path outputPath(const RenderSettings& settings, const std::string& scene, bool several) {
  if (!several && !settings.output.empty()) return settings.output;
  fs::path name = fs::path(scene).stem().string() + ".exr";
  return several && !settings.output.empty() ? fs::path(settings.output) / name : name;
}

/// The scenes to render: the positional ones, then --scene-list's (one path
/// per line, relative to the list's folder; blank lines and # comments skipped).
std::vector<std::string> sceneFiles(const RenderSettings& settings) {
  std::vector<std::string> scenes = settings.scenes;
  if (!settings.sceneList.empty()) {
    std::ifstream in(settings.sceneList);
    if (!in) throw UsageError(str("--scene-list: cannot read \"", settings.sceneList, "\""));
    const fs::path base = fs::path(settings.sceneList).parent_path();
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      line.erase(0, line.find_first_not_of(" \t\r"));
      line.erase(line.find_last_not_of(" \t\r") + 1);
      if (line.empty() || line[0] == '#') continue;
      fs::path path = fs::path(line).is_absolute() ? fs::path(line) : base / line;
      if (!fs::is_regular_file(path))
        throw UsageError(str(settings.sceneList, ":", number, ": no scene file \"", path.string(), "\""));
      scenes.push_back(path.string());
    }
  }
  if (scenes.empty()) throw UsageError("no scene: give a scene file (or --scene-list FILE)");
  return scenes;
}

/// Several scenes write into one folder: -o must name one, and no two scenes
/// may share an output name.
void checkSeveralOutputs(const RenderSettings& settings, const std::vector<std::string>& scenes) {
  if (!settings.output.empty()) {
    const fs::path out(settings.output);
    const std::string ext = out.extension().string();
    if ((fs::exists(out) && !fs::is_directory(out)) || ext == ".exr" || ext == ".npy" || ext == ".png")
      throw UsageError(str("-o \"", settings.output, "\": with ", scenes.size(),
                           " scenes -o names a folder (each scene writes <folder>/<scene name>.exr)"));
  }
  std::map<std::string, std::string> byName;
  for (const std::string& scene : scenes) {
    const std::string name = outputPath(settings, scene, true).string();
    auto [it, fresh] = byName.emplace(name, scene);
    if (!fresh)
      throw UsageError(str("\"", it->second, "\" and \"", scene, "\" would both write ", name,
                           ": render them with separate -o folders"));
  }
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

/// --resume: what makes a render's outputs (the scene file's bytes, FNV-1a,
/// and every option that changes them). A finished render writes it, with
/// the size of every file it wrote, to <stem>.femto-done beside them.
std::string renderKey(const RenderSettings& settings, const std::string& scene) {
  std::ifstream in(scene, std::ios::binary);
  uint64_t hash = 1469598103934665603ull;
  for (char c; in.get(c);) hash = (hash ^ uint64_t(static_cast<unsigned char>(c))) * 1099511628211ull;
  std::vector<std::string> defines = settings.defines;
  std::sort(defines.begin(), defines.end());
  std::ostringstream key;
  key << "scene " << fs::absolute(scene).lexically_normal().string() << " fnv1a " << std::hex << hash << std::dec
      << " seed " << settings.seed << " spp " << settings.sampleCount << " passes " << settings.passes
      << " time-limit " << settings.timeLimit << ' ' << settings.timeClock << " resolution " << settings.resolution
      << " integrator " << settings.integratorFile;
  for (const std::string& d : defines) key << " -D " << d;
  return key.str();
}

fs::path doneMarker(const fs::path& output) {
  return output.parent_path() / (output.stem().string() + ".femto-done");
}

/// The files a render to `output` wrote since `start`: <stem>.* and <stem>_*
/// beside it, and the files of <stem>_frames/.
std::vector<fs::path> writtenFiles(const fs::path& output, fs::file_time_type start) {
  const fs::path folder = output.parent_path().empty() ? fs::path(".") : output.parent_path();
  const std::string stem = output.stem().string();
  const fs::path marker = doneMarker(output).filename();
  std::vector<fs::path> files;
  auto ours = [&](const fs::path& name) {
    const std::string n = name.string();
    return n.size() > stem.size() && n.compare(0, stem.size(), stem) == 0 &&
           (n[stem.size()] == '.' || n[stem.size()] == '_') && name != marker;
  };
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (!ours(entry.path().filename())) continue;
    if (entry.is_directory() && entry.path().filename() == stem + "_frames") {
      for (const auto& frame : fs::directory_iterator(entry.path()))
        if (frame.is_regular_file()) files.push_back(frame.path());
    } else if (entry.is_regular_file() && entry.last_write_time() >= start) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Temporaries a killed render to `output` left (.tmp-<pid>-<stem>... beside
/// it, write_atomically.inl and transient_output.cpp name them so), when
/// their process is gone.
void removeStaleTemporaries(const fs::path& output) {
  const fs::path folder = output.parent_path().empty() ? fs::path(".") : output.parent_path();
  const std::string stem = output.stem().string();
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(".tmp-", 0) != 0) continue;
    const size_t dash = name.find('-', 5);
    if (dash == std::string::npos) continue;
    const std::string rest = name.substr(dash + 1);
    if (rest.size() <= stem.size() || rest.compare(0, stem.size(), stem) != 0 ||
        (rest[stem.size()] != '.' && rest[stem.size()] != '_'))
      continue;
    const long pid = std::strtol(name.c_str() + 5, nullptr, 10);
    if (pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH) fs::remove(entry.path(), error);
  }
}

void writeDoneMarker(const fs::path& output, const std::string& key, fs::file_time_type start) {
  const fs::path marker = doneMarker(output), temporary = marker.string() + ".tmp";
  const std::vector<fs::path> files = writtenFiles(output, start);  // before the marker exists
  {
    std::ofstream out(temporary);
    out << "femto render done\nkey " << key << '\n';
    for (const fs::path& file : files)
      out << "file " << fs::file_size(file) << ' ' << fs::relative(file, marker.parent_path().empty() ? "." : marker.parent_path()).string() << '\n';
    if (!out) throw Error(str("cannot write ", marker.string()));
  }
  fs::rename(temporary, marker);
}

/// Did a finished render with these settings write `output`, every file it
/// wrote still there at its size?
bool renderDone(const fs::path& output, const std::string& key) {
  std::ifstream in(doneMarker(output));
  std::string line;
  if (!std::getline(in, line) || line != "femto render done") return false;
  if (!std::getline(in, line) || line != "key " + key) return false;
  const fs::path folder = doneMarker(output).parent_path();
  int files = 0;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string word, name;
    uintmax_t bytes = 0;
    if (!(fields >> word >> bytes) || word != "file") return false;
    std::getline(fields >> std::ws, name);
    std::error_code error;
    if (fs::file_size(folder / name, error) != bytes || error) return false;
    ++files;
  }
  return files > 0;
}

int renderHere(const RenderSettings& settings, const RenderProcesses& processes, const std::string& sceneFile,
               const fs::path& outputFile) {
  settings.applyPluginDirs();
  // Parse every argument before the (possibly slow) scene load.
  LoadOptions load = loadOptions(settings);
  RenderOptions options;
  options.threads = settings.threads;
  options.seed = settings.seed;
  applyTimeLimit(settings, options);
  options.output = outputFile;
  const std::string key = settings.resume ? renderKey(settings, sceneFile) : std::string();
  if (settings.resume && renderDone(options.output, key)) {
    if (processes.writes())
      std::cout << "skipped " << options.output.string() << ": a finished render of the same settings wrote it ("
              << doneMarker(options.output).string() << ")\n";
    return 0;
  }
  // A marker of other settings no longer describes the files this render replaces.
  std::error_code staleMarker;
  if (settings.resume && processes.writes()) {
    fs::remove(doneMarker(options.output), staleMarker);
    removeStaleTemporaries(options.output);
  }
  // Under mpirun only rank 0 writes and draws; the others render tiles for it.
  options.progress = !settings.noProgress && processes.writes();
  if (processes.writes()) checkOutputWritable(options.output);

  std::optional<tbb::global_control> threadLimit;
  if (settings.threads > 0)
    threadLimit.emplace(tbb::global_control::max_allowed_parallelism, size_t(settings.threads));

  std::shared_ptr<Scene> scene = loadScene(sceneFile, load);
  scene->sensor().film().checkOutputPath(options.output);
  const fs::path output = options.output;
  if (!processes.writes()) options.output.clear();
  InterruptGuard interrupt;
  options.cancel = &interrupt.cancelFlag();
  const auto start = std::chrono::steady_clock::now();
  // File times are coarse on some file systems: a second's margin.
  const fs::file_time_type fileStart = fs::file_time_type::clock::now() - std::chrono::seconds(2);
  RenderStats stats = scene->integrator().render(*scene, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!processes.writes()) return 0;
  printSummary(output, stats, seconds, interrupt.interrupted(), settings,
               int(scene->sensor().sampler().sampleCount()));
  if (settings.resume && stats.completed && !interrupt.interrupted()) writeDoneMarker(output, key, fileStart);
  // 128 + SIGINT tells scripts the image is partial.
  return interrupt.interrupted() ? 130 : 0;
}

/// Every scene in turn (one process, or all ranks sharing each scene's
/// tiles), or, with more scenes than ranks, scene i on rank i mod ranks
/// alone. A scene that fails is reported and the others still render (exit 1
/// at the end); Ctrl-C stops after the scene it interrupted (exit 130).
int renderScenes(const RenderSettings& settings, RenderProcesses& processes, const std::vector<std::string>& scenes) {
  const bool several = scenes.size() > 1;
  if (!several) return renderHere(settings, processes, scenes[0], outputPath(settings, scenes[0], false));
  const bool alone = processes.count() > 1 && int(scenes.size()) > processes.count();
  if (alone) processes.shareTiles(false);
  if (processes.writes() && !settings.output.empty()) requireWritableFolder(settings.output, settings.output, true);
  int failed = 0;
  for (size_t i = 0; i < scenes.size(); ++i) {
    if (alone && int(i % size_t(processes.count())) != processes.rank()) continue;
    int code = 1;
    try {
      code = renderHere(settings, processes, scenes[i], outputPath(settings, scenes[i], true));
    } catch (const UsageError&) {
      throw;
    } catch (const std::exception& e) {
      // Ranks sharing a scene's tiles cannot go on without the one that failed.
      if (processes.sharesTiles()) throw;
      std::cerr << str("error: ", scenes[i], ": ", e.what(), '\n') << std::flush;
    }
    if (code == 130) return code;
    failed += code != 0;
  }
  if (failed > 0) {
    std::cerr << str("error: ", failed, " of ", scenes.size(), " scenes failed", alone ? str(" on rank ", processes.rank()) : "",
                     '\n');
    return 1;
  }
  return 0;
}

int render(const RenderSettings& settings) {
  const std::vector<std::string> scenes = sceneFiles(settings);
  if (scenes.size() > 1) checkSeveralOutputs(settings, scenes);
  RenderProcesses processes;
  if (processes.count() == 1) return renderScenes(settings, processes, scenes);
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
    return renderScenes(settings, processes, scenes);
  } catch (const std::exception& e) {
    processes.abortJob(e.what());
  }
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto s = std::make_shared<RenderSettings>();
  CLI::App* command = app.add_subcommand("render", "Render a Mitsuba XML scene to an OpenEXR image");
  command->add_option("scene", s->scenes, "Scene files (Mitsuba 0.6 or 3 XML); several render one after another")
      ->check(CLI::ExistingFile);
  command->add_option("--scene-list", s->sceneList, "Also render the scenes this file names, one per line")
      ->type_name("FILE")
      ->check(CLI::ExistingFile);
  command->add_flag("--resume", s->resume,
                    "Skip scenes a finished render with the same settings wrote (<name>.femto-done beside them)");
  addOutputOption(*command, s->output,
                  "Output image (default: <scene name>.exr in the current directory); with several scenes a folder");
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
