#pragma once
// Creating plugin objects in tests without a scene file: build the
// Properties by hand and ask the PluginManager (plugins are found in
// <test executable dir>/plugins or FEMTO_PLUGIN_PATH).
#include <memory>
#include <string>

#include <femto/core/plugin.h>
#include <femto/core/properties.h>

namespace femto::test {

template <typename T>
std::shared_ptr<T> createPlugin(ObjectKind kind, const Properties& props) {
  auto object = std::dynamic_pointer_cast<T>(PluginManager::instance().create(kind, props));
  if (!object) throw Error(str("plugin \"", props.pluginName(), "\" did not create the expected class"));
  return object;
}

/// The message of the femto::Error `f` throws ("" and a test failure if none).
template <typename F>
std::string errorMessageOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a femto::Error";
  return "";
}

}  // namespace femto::test
