// The render driver for Python: the scene's integrator renders to files (as
// `femto render -o` does, so the arrays are the CLI's, bit for bit) on a
// thread of its own with the GIL released, while the calling Python thread
// waits, checks for Ctrl-C (PyErr_CheckSignals: Python runs signal handlers
// only on its main thread) and calls the progress callback. A Ctrl-C or a
// callback that raises sets RenderOptions::cancel: the tiles in flight finish,
// the partial outputs are written, and the exception is handed back to the
// Python side, which raises it with the partial result attached.
#include <pybind11/stl/filesystem.h>

#include <tbb/global_control.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <femto/core/duration.h>
#include <femto/render/film.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>

#include "bindings.h"

namespace py = pybind11;

namespace femto::python {
namespace {

/// How often the waiting Python thread looks for Ctrl-C when nothing else wakes it.
constexpr auto SignalPollInterval = std::chrono::milliseconds(50);

/// What the render thread tells the waiting Python thread.
struct Mailbox {
  std::mutex mutex;
  std::condition_variable wake;
  std::optional<ProgressState> report;  // the newest, not yet delivered
  bool done = false;
};

py::object progressObject(const ProgressState& s) {
  py::dict d;
  d["label"] = s.label;
  d["fraction"] = s.fraction;
  d["elapsed"] = s.elapsedSeconds;
  d["eta"] = s.etaSeconds >= 0 ? py::object(py::float_(s.etaSeconds)) : py::none();
  d["finished"] = s.finished;
  return d;
}

py::dict render(const std::shared_ptr<Scene>& scene, const std::filesystem::path& output, uint64_t seed, int threads,
                const py::object& progress, int passes, double timeLimit, const std::string& timeClock) {
  scene->sensor().film().checkOutputPath(output);
  RenderOptions options;
  options.output = output;
  options.seed = seed;
  options.threads = threads;
  options.passes = passes;
  options.timeLimit = timeLimit;
  options.timeClock = timeClock == "cpu" ? RenderClock::Cpu : RenderClock::Wall;
  // The terminal bar only when nobody else shows progress (it draws on a TTY only, as in the CLI).
  options.progress = progress.is_none();
  std::atomic<bool> cancel{false};
  options.cancel = &cancel;
  Mailbox mailbox;
  if (!progress.is_none())
    options.onProgress = [&mailbox](const ProgressState& s) {
      std::lock_guard<std::mutex> lock(mailbox.mutex);
      mailbox.report = s;
      mailbox.wake.notify_one();
    };

  RenderStats stats;
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      // As the CLI's -t: caps TBB for everything the render does, not only the tile loop.
      std::optional<tbb::global_control> limit;
      if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));
      stats = scene->integrator().render(*scene, options);
    } catch (...) {
      failure = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(mailbox.mutex);
    mailbox.done = true;
    mailbox.wake.notify_one();
  });

  py::object stoppedBy = py::none();  // the Python exception that cancelled the render
  for (bool done = false; !done;) {
    std::optional<ProgressState> report;
    {
      py::gil_scoped_release release;
      std::unique_lock<std::mutex> lock(mailbox.mutex);
      mailbox.wake.wait_for(lock, SignalPollInterval, [&] { return mailbox.done || mailbox.report; });
      done = mailbox.done;
      report.swap(mailbox.report);
    }
    if (!stoppedBy.is_none()) continue;  // stopping: wait for the tiles in flight, call nothing
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (report) progress(progressObject(*report));
    } catch (py::error_already_set& e) {
      stoppedBy = e.value();
      cancel = true;
    }
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (failure) std::rethrow_exception(failure);
  py::dict d;
  d["completed"] = stats.completed;
  d["samples"] = stats.samples;
  d["invalid_samples"] = stats.invalidSamples;
  d["seconds"] = stats.seconds;
  d["cpu_seconds"] = stats.cpuSeconds;
  d["passes"] = stats.passes;
  d["spp_per_pass"] = scene->sensor().sampler().sampleCount();
  d["time_limit_reached"] = stats.timeLimitReached;
  d["stopped_by"] = stoppedBy;
  return d;
}

}  // namespace

void bindRender(py::module_& m) {
  m.def("render", &render, py::arg("scene"), py::arg("output"), py::arg("seed"), py::arg("threads"),
        py::arg("progress"), py::arg("passes") = 0, py::arg("time_limit") = 0.0, py::arg("time_clock") = "wall",
        "Render `scene` to `output` (the files `femto render -o output` writes); returns the render's statistics "
        "and the Python exception (KeyboardInterrupt, or one the progress callback raised) that stopped it, if any");
  m.def("parse_duration", &parseDuration, py::arg("text"), "Seconds in \"30s\", \"5m\", \"1.5h\" or \"90\" (femto render --time-limit)");
}

}  // namespace femto::python
