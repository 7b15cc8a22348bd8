#include "upgrade_names.h"

#include <cctype>

namespace femto::xml {

std::string camelToSnake(std::string_view name) {
  // A one-letter name (mitchell's "B" and "C") is spelt the same in both
  // dialects: there is no word boundary to mark.
  if (name.size() == 1) return std::string(name);
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
  if (node.dialect != UnknownDialect && node.dialect < 2) {
    for (auto& [key, value] : node.attributes)
      if (key == "name") value = camelToSnake(value);
  }
  for (auto& child : node.children) upgradeLegacyNames(child);
}

namespace {

/// What a Mitsuba integrator name becomes: the femto plugin, and the
/// max_depth the original defaults to when it differs from femto's -1
/// (0 = keep femto's).
struct IntegratorUpgrade {
  std::string type;
  int defaultMaxDepth = 0;
};

// Mitsuba's volumetric path tracers are transient_path (which renders steady
// films too). Mitsuba 3's differentiable integrators render, in a forward
// render, what their plain counterparts do; as Python ADIntegrators their
// max_depth defaults to 6.
IntegratorUpgrade upgradeIntegrator(const std::string& type) {
  if (type == "volpath" || type == "volpath_simple" || type == "volpathmis") return {"transient_path"};
  if (type == "prbvolpath") return {"transient_path", 6};
  if (type == "prb" || type == "prb_basic" || type == "prb_projective") return {"path", 6};
  if (type == "direct_projective") return {"direct"};
  return {type};
}

bool hasParameter(const XmlNode& node, const std::string& name) {
  for (const auto& child : node.children)
    if (const std::string* n = child.attribute("name"); n && *n == name) return true;
  return false;
}

}  // namespace

std::string upgradePluginType(std::string_view tag, const std::string& type) {
  return tag == "integrator" ? upgradeIntegrator(type).type : type;
}

void upgradePluginTypes(XmlNode& node) {
  if (const std::string* type = node.attribute("type"); type && node.tag == "integrator") {
    IntegratorUpgrade upgrade = upgradeIntegrator(*type);
    if (upgrade.defaultMaxDepth != 0 && !hasParameter(node, "max_depth")) {
      XmlNode depth;
      depth.tag = "integer";
      depth.attributes = {{"name", "max_depth"}, {"value", std::to_string(upgrade.defaultMaxDepth)}};
      depth.location = node.location;
      depth.source = node.source;
      depth.dialect = node.dialect;
      node.children.push_back(std::move(depth));
    }
    node.setAttribute("type", upgrade.type);
  } else if (type) {
    node.setAttribute("type", upgradePluginType(node.tag, *type));
  }
  for (auto& child : node.children) upgradePluginTypes(child);
}

}  // namespace femto::xml
