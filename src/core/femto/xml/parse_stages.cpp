#include "parse_stages.h"

namespace femto::xml {
namespace fs = std::filesystem;

ParsedScene parseTree(XmlNode root, const fs::path& sceneDir, const LoadOptions& options) {
  ParsedScene parsed{std::move(root), ExpandResult{FileResolver(sceneDir), {}, {}}, {}};
  parsed.expanded = expandDirectives(parsed.root, sceneDir, options.defines);
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
