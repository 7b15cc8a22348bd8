#include "parse_stages.h"

#include <optional>

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

/// --integrator FILE, before expansion: an <include> of it after the scene's
/// own elements (so it sees the scene's $names).
fs::path includeIntegratorFile(XmlNode& root, const fs::path& file) {
  std::error_code ec;
  fs::path absolute = fs::absolute(file, ec);
  if (ec || !fs::is_regular_file(absolute)) throw Error(str("--integrator: no such file \"", file.string(), "\""));
  XmlNode include;
  include.tag = "include";
  include.attributes.emplace_back("filename", absolute.string());
  include.location = root.location;
  include.source = root.source;
  include.dialect = root.dialect;
  root.children.push_back(std::move(include));
  return absolute;
}

/// After expansion: the root's <integrator> elements from other files than
/// the --integrator file go (the scene's own, wherever it was included from).
void keepIntegratorOf(XmlNode& root, const fs::path& file) {
  auto fromFile = [&](const XmlNode& node) {
    std::error_code ec;
    return node.source && fs::equivalent(node.source->file, file, ec);
  };
  bool found = false;
  std::vector<XmlNode> kept;
  for (XmlNode& child : root.children) {
    if (child.tag != "integrator") {
      kept.push_back(std::move(child));
    } else if (fromFile(child)) {
      found = true;
      kept.push_back(std::move(child));
    }
  }
  if (!found) throw Error(str("--integrator \"", file.string(), "\" holds no <integrator> element"));
  root.children = std::move(kept);
}

}  // namespace

ParsedScene parseTree(XmlNode root, const fs::path& sceneDir, const LoadOptions& options) {
  ParsedScene parsed{std::move(root), ExpandResult{FileResolver(sceneDir), {}, {}, {}}, {}};
  std::optional<fs::path> integratorFile;
  if (options.integratorFile) integratorFile = includeIntegratorFile(parsed.root, *options.integratorFile);
  parsed.expanded = expandDirectives(parsed.root, sceneDir, options.defines);
  if (integratorFile) keepIntegratorOf(parsed.root, *integratorFile);
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
