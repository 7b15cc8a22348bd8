// Scene loading (the CLI's loader, with its LoadOptions: -D, --strict,
// --spp, --resolution), what a result needs to know about the scene (film
// size, crop, time axis), and the plugin list (`femto plugins`).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>

#include <femto/core/plugin.h>
#include <femto/film/transient_film.h>
#include <femto/render/emitter.h>
#include <femto/render/film.h>
#include <femto/render/integrator.h>
#include <femto/render/medium.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/render/shape.h>
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

/// The objects whose parameters may change after loading, by the names
/// Scene.set takes: "film", "sampler", and every object with an id (emitters,
/// media of shapes, emitters and the sensor).
std::vector<std::pair<std::string, Object*>> editableObjects(Scene& scene) {
  std::vector<std::pair<std::string, Object*>> objects;
  auto add = [&](const std::string& name, const Object* object) {
    if (!object || name.empty()) return;
    for (const auto& [n, o] : objects)
      if (o == object || n == name) return;
    if (!object->editableParameters().empty()) objects.emplace_back(name, const_cast<Object*>(object));
  };
  const Sensor& sensor = scene.sensor();
  add("film", &sensor.film());
  add("sampler", &sensor.sampler());
  add(sensor.medium() ? sensor.medium()->id() : "", sensor.medium());
  for (const auto& e : scene.emitters()) {
    add(e->id(), e.get());
    add(e->medium() ? e->medium()->id() : "", e->medium());
  }
  for (const auto& s : scene.shapes()) {
    add(s->interiorMedium() ? s->interiorMedium()->id() : "", s->interiorMedium());
    add(s->exteriorMedium() ? s->exteriorMedium()->id() : "", s->exteriorMedium());
    if (const Emitter* e = s->emitter()) add(e->id().empty() ? s->id() : e->id(), e);
  }
  return objects;
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
      .def("parameters",
           [](Scene& scene) {
             py::dict values;  // "object.parameter" -> a number, or a tuple of 3 for a colour
             for (const auto& [name, object] : editableObjects(scene))
               for (const auto& [p, value] : object->editableParameters())
                 values[py::str(name + "." + p)] =
                     value.size() == 1 ? py::object(py::float_(value[0])) : py::object(py::tuple(py::cast(value)));
             return values;
           })
      .def(
          "set_parameter",
          [](Scene& scene, const std::string& key, const std::vector<double>& value) {
            const size_t dot = key.rfind('.');
            if (dot == std::string::npos)
              throw Error(str("\"", key, "\": name a parameter as OBJECT.PARAMETER (scene.parameters() lists them)"));
            const std::string name = key.substr(0, dot), parameter = key.substr(dot + 1);
            for (const auto& [n, object] : editableObjects(scene))
              if (n == name) return object->setParameter(parameter, value);
            std::string known;
            for (const auto& [n, object] : editableObjects(scene)) known += (known.empty() ? "" : ", ") + n;
            throw Error(str("\"", key, "\": no object \"", name, "\" with parameters that can change (", known, ")"));
          },
          py::arg("key"), py::arg("value"))
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
