#include "parse_stages.h"

#include <femto/core/log.h>

namespace femto::xml {
namespace fs = std::filesystem;

namespace {

/// A -D the scene never refers to is most likely a typo (or meant for an
/// include the scene did not select): like an unused plugin parameter, it is
/// a warning, or an error with --strict.
void reportUnusedDefines(const ExpandResult& expanded, const XmlNode& root, const LoadOptions& options) {
  for (const auto& name : expanded.unusedDefines) {
    std::string file = root.source ? root.source->file : std::string("<scene>");
    std::string message = str(file, ": -D ", name, "=", options.defines.at(name), " was not used: the scene never refers to $",
                              name);
    if (options.strict) throw Error(message);
    logWarn(message);
  }
}

}  // namespace

ParsedScene parseTree(XmlNode root, const fs::path& sceneDir, const LoadOptions& options) {
  ParsedScene parsed{std::move(root), ExpandResult{FileResolver(sceneDir), {}, {}, {}}, {}};
  parsed.expanded = expandDirectives(parsed.root, sceneDir, options.defines);
  reportUnusedDefines(parsed.expanded, parsed.root, options);
  upgradeLegacyNames(parsed.root);
  upgradePluginTypes(parsed.root);
  parsed.index = resolveReferences(parsed.root, parsed.expanded.aliases);
  return parsed;
}

ParsedScene parseString(const std::string& xml, const fs::path& sceneDir, const LoadOptions& options,
                        const std::string& virtualName) {
  return parseTree(readXmlString(xml, virtualName), sceneDir, options);
}

ParsedScene parseFile(const fs::path& file, const LoadOptions& options) {
  return parseTree(readXmlFile(file), fs::absolute(file).parent_path(), options);
}

ObjectRef buildObject(const ParsedScene& parsed, const LoadOptions& options, ObjectFactory& factory) {
  ObjectBuilder builder(parsed.expanded, parsed.index, options, factory);
  if (!kindFromTag(parsed.root.tag)) throw sceneError(parsed.root, str("unsupported tag <", parsed.root.tag, ">"));
  return builder.build(parsed.root);
}

}  // namespace femto::xml
