#pragma once
// Parse stage 4: index objects by id="" and point every <ref id> at its object.
#include <map>
#include <set>
#include <string>

#include "xml_node.h"

namespace femto::xml {

struct ObjectIndex {
  std::map<std::string, const XmlNode*> byId;
  /// Ids some <ref> names: such objects belong to their referrers, not to the scene.
  std::set<std::string> referenced;
};

/// Throws (file:line, echoed) for a duplicate id, a <ref> without id, and a
/// <ref> to an unknown id (with close ids suggested), and references that make
/// a cycle (an object that contains itself, directly or through others). `aliases` maps as="" names to ids.
ObjectIndex resolveReferences(XmlNode& root, const std::map<std::string, std::string>& aliases);

}  // namespace femto::xml
