// A plugin as a femto with another plugin ABI would build it: must be refused
// before its create function is called.
#include <cstdlib>

#include <femto/core/plugin.h>

FEMTO_PLUGIN_EXPORT const femto::PluginDescriptor* femto_plugin_descriptor() {
  static const femto::PluginDescriptor descriptor{
      femto::FemtoAbiVersion + 1, femto::ObjectKind::Texture, "test_wrong_abi", "built for another ABI",
      [](const femto::Properties&) -> femto::Object* { std::abort(); }};
  return &descriptor;
}
