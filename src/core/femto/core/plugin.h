#pragma once
// Plugins: one shared library per plugin, exporting a single C entry point
// `femto_plugin_descriptor` that returns a PluginDescriptor. The core refuses a
// library built against another core ABI, by name, before calling into it.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <femto/core/object.h>
#include <femto/core/properties.h>

namespace femto {

/// Bump whenever a class a plugin derives from or calls changes layout or
/// virtual table. A plugin built against another value is refused.
inline constexpr uint32_t FemtoAbiVersion = 9;

struct PluginDescriptor {
  uint32_t abiVersion;     // FemtoAbiVersion at the plugin's build time
  ObjectKind kind;         // what it creates
  const char* name;        // the type="" it answers to (also the library's file name)
  const char* description; // one line, shown by `femto plugins`
  Object* (*create)(const Properties& props);
};

inline constexpr const char* PluginEntryPoint = "femto_plugin_descriptor";

/// The library file name of a plugin ("diffuse" -> "diffuse.so").
std::string pluginFileName(const std::string& name);

class PluginManager {
 public:
  /// The process-wide manager. Its search path starts with
  /// <executable dir>/plugins, <executable dir>/../lib/femto/plugins, then the
  /// directories of FEMTO_PLUGIN_PATH (colon-separated).
  static PluginManager& instance();

  /// Put `dir` first in the search path (`femto render -p DIR`).
  void prependSearchPath(const std::filesystem::path& dir);
  const std::vector<std::filesystem::path>& searchPath() const { return searchPath_; }

  /// Load (once) and return the descriptor of plugin `name`. Throws femto::Error
  /// with one sentence naming the plugin and the paths tried when it is
  /// missing, not a femto plugin, or built against another ABI. Names with path
  /// components or characters outside [A-Za-z0-9_-] are refused.
  const PluginDescriptor& load(const std::string& name);
  /// Load a plugin from an explicit file (tests, tools).
  const PluginDescriptor& loadFile(const std::filesystem::path& file);

  /// Create an object. Throws if the plugin does not make objects of `expected` kind.
  ObjectRef create(ObjectKind expected, const Properties& props);

  /// Names of plugins loaded so far (for tests: a scene loads only what it names).
  std::vector<std::string> loadedPlugins() const;
  /// Every plugin library found on the search path, loaded to read its descriptor
  /// (for `femto plugins`). Libraries that fail to load are skipped with a warning.
  std::vector<const PluginDescriptor*> discoverAll();
  /// Names of all plugin files found on the search path (without loading them).
  std::vector<std::string> availableNames() const;

  static bool validName(const std::string& name);

 private:
  PluginManager();
  struct Library;
  const PluginDescriptor& openLocked(const std::filesystem::path& file);
  mutable std::mutex mutex_;
  std::vector<std::filesystem::path> searchPath_;
  std::vector<std::unique_ptr<Library>> libraries_;
};

}  // namespace femto

#define FEMTO_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

/// Export `Class` (constructible from `const Properties&`) as plugin `Name`:
///   FEMTO_EXPORT_PLUGIN(DiffuseBSDF, BSDF, "diffuse", "Lambertian reflector")
#define FEMTO_EXPORT_PLUGIN(Class, Kind, Name, Description)                                      \
  FEMTO_PLUGIN_EXPORT const ::femto::PluginDescriptor* femto_plugin_descriptor() {               \
    static const ::femto::PluginDescriptor descriptor{                                         \
        ::femto::FemtoAbiVersion, ::femto::ObjectKind::Kind, Name, Description,                \
        [](const ::femto::Properties& props) -> ::femto::Object* { return new Class(props); }}; \
    return &descriptor;                                                                        \
  }
