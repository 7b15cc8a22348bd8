// femto._femto: the compiled half of the `femto` Python package (docs/python.md).
#include <dlfcn.h>

#include <filesystem>

#include <femto/core/plugin.h>

#include "bindings.h"

namespace femto::python {
namespace {

/// The plugins of the build tree: this module lives in <build>/python/femto/,
/// the plugins in <build>/bin/plugins. The core's own search path starts
/// beside the executable, which here is the Python interpreter.
void addBuildTreePlugins() {
  Dl_info info{};
  if (!dladdr(reinterpret_cast<void*>(&addBuildTreePlugins), &info) || !info.dli_fname) return;
  std::error_code ec;
  std::filesystem::path module = std::filesystem::canonical(info.dli_fname, ec);
  if (ec) return;
  std::filesystem::path plugins = module.parent_path().parent_path().parent_path() / "bin" / "plugins";
  if (std::filesystem::is_directory(plugins, ec)) PluginManager::instance().prependSearchPath(plugins);
}

}  // namespace
}  // namespace femto::python

PYBIND11_MODULE(_femto, m) {
  m.doc() = "femto's renderer, bound for Python (use the `femto` package, not this module)";
  m.attr("abi_version") = femto::FemtoAbiVersion;
  femto::python::addBuildTreePlugins();
  femto::python::bindSceneError(m);
  femto::python::bindScene(m);
  femto::python::bindRender(m);
  femto::python::bindImages(m);
  femto::python::bindView(m);
}
