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

/// Depth-first walk over what each object needs (nested objects and ref
/// targets). `onWalk[n]` is false while n is being walked, true when finished;
/// reaching an object that is still being walked means a reference cycle.
void checkCycles(const XmlNode& node, std::map<const XmlNode*, bool>& onWalk) {
  if (node.tag != "ref") {
    for (const auto& c : node.children) checkCycles(c, onWalk);
    return;
  }
  const XmlNode* target = node.target;
  auto it = onWalk.find(target);
  if (it != onWalk.end()) {
    if (!it->second)
      throw sceneError(node, str("reference to \"", target->attributeOr("id", ""),
                                 "\" makes a cycle (an object cannot contain itself)"));
    return;
  }
  onWalk[target] = false;
  for (const auto& c : target->children) checkCycles(c, onWalk);
  onWalk[target] = true;
}

}  // namespace

ObjectIndex resolveReferences(XmlNode& root, const std::map<std::string, std::string>& aliases) {
  ObjectIndex index;
  collectIds(root, index);
  linkRefs(root, aliases, index);
  std::map<const XmlNode*, bool> onWalk;
  for (const auto& [id, node] : index.byId) {
    if (onWalk.count(node)) continue;
    onWalk[node] = false;
    for (const auto& c : node->children) checkCycles(c, onWalk);
    onWalk[node] = true;
  }
  return index;
}

}  // namespace femto::xml
