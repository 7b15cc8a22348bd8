#pragma once
// Nested objects with Mitsuba's defaults: a sensor without <film> gets an
// hdrfilm, a scene without <integrator> a path tracer, and so on.
#include <memory>

#include <femto/core/plugin.h>
#include <femto/core/properties.h>

namespace femto {

/// The single nested object of `kind` in `props`, or, when there is none, a
/// new one from plugin `fallback` with default parameters. Throws if the
/// nested object is not a `T` (or the fallback plugin cannot be loaded).
template <typename T>
std::shared_ptr<T> nestedOrDefault(const Properties& props, ObjectKind kind, const char* fallback,
                                   const std::string& except = "") {
  ObjectRef obj = props.objectOfKind(kind, except);
  if (!obj) {
    Properties defaults(fallback);
    defaults.setLocation(props.location());
    obj = PluginManager::instance().create(kind, defaults);
  }
  auto typed = std::dynamic_pointer_cast<T>(obj);
  if (!typed) throw Error(props.location(), str("the nested <", kindTag(kind), "> of \"", props.pluginName(),
                                               "\" does not implement the expected interface"));
  return typed;
}

}  // namespace femto
