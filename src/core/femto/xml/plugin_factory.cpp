// The real ObjectFactory: plugins through PluginManager, the scene from the core.
#include <algorithm>

#include <femto/core/plugin.h>
#include <femto/core/spelling.h>
#include <femto/render/scene.h>

#include "build_objects.h"

namespace femto::xml {
namespace {

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
      if (std::find(available.begin(), available.end(), name) == available.end())
        throw Error(str("unknown <", kindTag(kind), "> plugin \"", name, "\"", didYouMean(name, available)));
      throw;
    }
    // PluginManager reports plugins of another kind and loading failures.
    return manager.create(kind, props);
  }
};

}  // namespace

std::unique_ptr<ObjectFactory> makePluginFactory() { return std::make_unique<PluginFactory>(); }

}  // namespace femto::xml
