#include "upgrade_names.h"

#include <cctype>

namespace femto::xml {

std::string camelToSnake(std::string_view name) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    auto c = static_cast<unsigned char>(name[i]);
    if (std::isupper(c) && i > 0) {
      auto prev = static_cast<unsigned char>(name[i - 1]);
      if (std::islower(prev) || std::isdigit(prev)) out += '_';
    }
    out += char(std::tolower(c));
  }
  return out;
}

void upgradeLegacyNames(XmlNode& node) {
  if (node.dialect != kUnknownDialect && node.dialect < 2) {
    for (auto& [key, value] : node.attributes)
      if (key == "name") value = camelToSnake(value);
  }
  for (auto& child : node.children) upgradeLegacyNames(child);
}

std::string upgradePluginType(std::string_view tag, const std::string& type) {
  if (tag == "integrator" && (type == "volpath" || type == "volpath_simple" || type == "volpathmis"))
    return "transient_path";
  return type;
}

void upgradePluginTypes(XmlNode& node) {
  for (auto& [key, value] : node.attributes)
    if (key == "type") value = upgradePluginType(node.tag, value);
  for (auto& child : node.children) upgradePluginTypes(child);
}

}  // namespace femto::xml
