#include "resolve_references.h"

#include <femto/core/object.h>
#include <femto/core/spelling.h>

#include "scene_error.h"

namespace femto::xml {
namespace {

void collectIds(const XmlNode& node, ObjectIndex& index) {
  if (kindFromTag(node.tag)) {
    if (const std::string* id = node.attribute("id"); id && !id->empty()) {
      auto [it, inserted] = index.byId.emplace(*id, &node);
      if (!inserted)
        throw sceneError(node, str("duplicate id \"", *id, "\" (first declared at ", it->second->location.toString(), ")"));
    }
  }
  for (const auto& c : node.children) collectIds(c, index);
}

void linkRefs(XmlNode& node, const std::map<std::string, std::string>& aliases, ObjectIndex& index) {
  if (node.tag == "ref") {
    const std::string* idAttr = node.attribute("id");
    if (!idAttr || idAttr->empty()) throw sceneError(node, "<ref> needs an id=\"...\" attribute");
    std::string id = *idAttr;
    if (auto alias = aliases.find(id); alias != aliases.end()) id = alias->second;
    auto it = index.byId.find(id);
    if (it == index.byId.end()) {
      std::vector<std::string> ids;
      for (const auto& entry : index.byId) ids.push_back(entry.first);
      throw sceneError(node, str("unresolved reference to id \"", id, "\"", didYouMean(id, ids)));
    }
    node.target = it->second;
    index.referenced.insert(id);
  }
  for (auto& c : node.children) linkRefs(c, aliases, index);
}

}  // namespace

ObjectIndex resolveReferences(XmlNode& root, const std::map<std::string, std::string>& aliases) {
  ObjectIndex index;
  collectIds(root, index);
  linkRefs(root, aliases, index);
  return index;
}

}  // namespace femto::xml
