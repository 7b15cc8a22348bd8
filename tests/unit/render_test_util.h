#pragma once
// Helpers shared by the render-core unit tests: plugin creation with the
// build tree's plugin folder on the search path, and scratch directories.
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>

#include <femto/core/plugin.h>
#include <femto/core/properties.h>

namespace femto::test {

/// Put the build tree's plugin folder first on the search path (once).
inline void usePluginsFromBuildTree() {
  static bool prepared = [] {
    PluginManager::instance().prependSearchPath(FEMTO_PLUGIN_DIR);
    return true;
  }();
  (void)prepared;
}

/// Create plugin object `props.pluginName()` of `kind`, cast to T.
template <typename T>
std::shared_ptr<T> makePlugin(ObjectKind kind, const Properties& props) {
  usePluginsFromBuildTree();
  return std::dynamic_pointer_cast<T>(PluginManager::instance().create(kind, props));
}

/// A fresh empty directory under the system temporary folder.
inline std::filesystem::path scratchDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("femto-test-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace femto::test
