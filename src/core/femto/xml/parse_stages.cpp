#include "parse_stages.h"

#include <optional>

#include <femto/core/log.h>
#include <femto/core/spelling.h>

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
                              name, didYouMean(name, expanded.parameterNames));
    if (options.strict) throw Error(message);
    logWarn(message);
  }
}

/// Marks where the --integrator file's elements start in the expanded root.
constexpr const char* IntegratorFileMark = "femto:integrator-file";

/// --integrator FILE, before expansion: a mark and an <include> of the file
/// after the scene's own elements (so it sees the scene's $names).
fs::path includeIntegratorFile(XmlNode& root, const fs::path& file) {
  std::error_code ec;
  fs::path absolute = fs::absolute(file, ec);
  if (ec || !fs::is_regular_file(absolute)) throw Error(str("--integrator: no such file \"", file.string(), "\""));
  XmlNode mark, include;
  mark.tag = IntegratorFileMark;
  include.tag = "include";
  include.attributes.emplace_back("filename", absolute.string());
  for (XmlNode* node : {&mark, &include}) {
    node->location = root.location;
    node->source = root.source;
    node->dialect = root.dialect;
  }
  root.children.push_back(std::move(mark));
  root.children.push_back(std::move(include));
  return absolute;
}

/// After expansion: the root's <integrator> elements before the mark (the
/// scene's own, wherever they were included from; the file may be one the
/// scene includes too) go, and the mark.
void keepIntegratorOf(XmlNode& root, const fs::path& file) {
  bool fromFile = false, found = false;
  std::vector<XmlNode> kept;
  for (XmlNode& child : root.children) {
    if (child.tag == IntegratorFileMark) {
      fromFile = true;
    } else if (child.tag != "integrator" || fromFile) {
      found = found || (fromFile && child.tag == "integrator");
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
