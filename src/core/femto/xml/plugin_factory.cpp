// The real ObjectFactory: plugins through PluginManager, the scene from the core.
#include <algorithm>

#include <femto/core/plugin.h>
#include <femto/core/spelling.h>
#include <femto/render/scene.h>

#include "build_objects.h"
#include "foreign_plugins.h"

namespace femto::xml {
namespace {

std::string searchPathList(const PluginManager& manager) {
  std::string out;
  for (const auto& dir : manager.searchPath()) out += (out.empty() ? "" : ", ") + dir.string();
  return out.empty() ? std::string("an empty plugin search path") : out;
}

class PluginFactory final : public ObjectFactory {
 public:
  ObjectRef create(ObjectKind kind, const Properties& props) override {
    if (kind == ObjectKind::Scene) return std::make_shared<Scene>(props);
    auto& manager = PluginManager::instance();
    const std::string& name = props.pluginName();
    try {
      manager.load(name);
    } catch (const Error&) {
      // Say "unknown plugin" in scene words when no such library exists; keep
      // PluginManager's sentence for libraries that exist but fail to load.
      auto available = manager.availableNames();
      if (std::find(available.begin(), available.end(), name) == available.end()) {
        // A near miss is most likely a typo; otherwise the user may have
        // forgotten `-p DIR`, so say where we looked.
        std::string hint = adviceForForeignPlugin(kind, name);
        if (hint.empty()) hint = didYouMean(name, available);
        if (hint.empty()) hint = " (no " + pluginFileName(name) + " in " + searchPathList(manager) + ")";
        throw Error(str("unknown <", kindTag(kind), "> plugin \"", name, "\"", hint));
      }
      throw;
    }
    // PluginManager reports plugins of another kind and loading failures.
    return manager.create(kind, props);
  }
};

}  // namespace

std::unique_ptr<ObjectFactory> makePluginFactory() { return std::make_unique<PluginFactory>(); }

}  // namespace femto::xml
