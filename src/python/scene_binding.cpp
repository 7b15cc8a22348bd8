// Scene loading (the CLI's loader, with its LoadOptions: -D, --strict,
// --spp, --resolution), what a result needs to know about the scene (film
// size, crop, time axis), and the plugin list (`femto plugins`).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>

#include <femto/core/plugin.h>
#include <femto/film/transient_film.h>
#include <femto/render/film.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/xml/loader.h>

#include "bindings.h"

namespace py = pybind11;

namespace femto::python {
namespace {

LoadOptions loadOptions(const std::map<std::string, std::string>& defines, bool strict, std::optional<int> spp,
                        std::optional<std::pair<int, int>> resolution) {
  LoadOptions options;
  options.defines = defines;
  options.strict = strict;
  options.sampleCount = spp;
  if (resolution) options.resolution = Point2i(resolution->first, resolution->second);
  return options;
}

/// The scene's film and time axis, as a dict the Python side turns into a result.
py::dict describe(const Scene& scene) {
  const Film& film = scene.sensor().film();
  py::dict d;
  d["film_size"] = py::make_tuple(film.size().x, film.size().y);
  d["crop_offset"] = py::make_tuple(film.cropOffset().x, film.cropOffset().y);
  d["crop_size"] = py::make_tuple(film.cropSize().x, film.cropSize().y);
  d["spp"] = scene.sensor().sampler().sampleCount();
  d["film"] = film.toString();
  d["integrator"] = scene.integrator().toString();
  d["extension"] = film.defaultExtension();
  const auto* transient = dynamic_cast<const TransientFilm*>(&film);
  d["transient"] = transient != nullptr;
  if (transient) {
    const TimeGrid& grid = transient->timeGrid();
    d["bins"] = grid.bins;
    d["start_opl"] = grid.start;
    d["bin_width_opl"] = grid.binWidth;
    d["writes_frames"] = transient->writesFrames();
  }
  return d;
}

/// The files a render to `output` writes (TransientFilm::outputPaths; a steady film writes `output` itself).
py::dict outputPaths(const Scene& scene, const std::filesystem::path& output) {
  py::dict d;
  const auto* transient = dynamic_cast<const TransientFilm*>(&scene.sensor().film());
  if (!transient) {
    d["steady"] = output;
    return d;
  }
  TransientFilm::OutputPaths paths = transient->outputPaths(output);
  d["volume"] = paths.volume;
  d["steady"] = paths.steady;
  d["before"] = paths.before;
  d["after"] = paths.after;
  d["frames"] = paths.framesDir;
  return d;
}

py::list plugins() {
  std::vector<const PluginDescriptor*> found = PluginManager::instance().discoverAll();
  std::sort(found.begin(), found.end(), [](const PluginDescriptor* a, const PluginDescriptor* b) {
    return std::pair(int(a->kind), std::string(a->name)) < std::pair(int(b->kind), std::string(b->name));
  });
  py::list list;
  for (const PluginDescriptor* p : found)
    list.append(py::make_tuple(std::string(p->name), std::string(kindTag(p->kind)),
                               std::string(p->description ? p->description : "")));
  return list;
}

}  // namespace

void bindScene(py::module_& m) {
  py::class_<Scene, std::shared_ptr<Scene>>(m, "Scene", "A loaded scene (use femto.load_file / femto.load_string)")
      .def("describe", &describe)
      .def("output_paths", &outputPaths, py::arg("output"))
      .def("__repr__", [](const Scene& s) { return "<femto scene: " + s.integrator().toString() + ">"; });
  m.def(
      "load_file",
      [](const std::filesystem::path& file, const std::map<std::string, std::string>& defines, bool strict,
         std::optional<int> spp, std::optional<std::pair<int, int>> resolution) {
        LoadOptions options = loadOptions(defines, strict, spp, resolution);
        py::gil_scoped_release release;  // meshes can take a while
        return loadScene(file, options);
      },
      py::arg("file"), py::arg("defines"), py::arg("strict"), py::arg("spp"), py::arg("resolution"));
  m.def(
      "load_string",
      [](const std::string& xml, const std::filesystem::path& baseDir,
         const std::map<std::string, std::string>& defines, bool strict, std::optional<int> spp,
         std::optional<std::pair<int, int>> resolution, const std::string& name) {
        LoadOptions options = loadOptions(defines, strict, spp, resolution);
        py::gil_scoped_release release;
        return loadSceneFromString(xml, baseDir, options, name);
      },
      py::arg("xml"), py::arg("base_dir"), py::arg("defines"), py::arg("strict"), py::arg("spp"), py::arg("resolution"),
      py::arg("name"));
  m.def("plugins", &plugins, "(name, kind, description) of every plugin on the search path");
  m.def(
      "add_plugin_dir", [](const std::filesystem::path& dir) { PluginManager::instance().prependSearchPath(dir); },
      "Search `dir` for plugins first (the CLI's -p)");
  m.def("plugin_search_path", [] { return PluginManager::instance().searchPath(); });
}

}  // namespace femto::python
