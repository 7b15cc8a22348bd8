#include "expand_directives.h"

#include <cctype>
#include <filesystem>

#include "read_xml.h"

namespace femto::xml {
namespace fs = std::filesystem;
namespace {

bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

void setDialect(XmlNode& node, int dialect) {
  node.dialect = dialect;
  for (auto& c : node.children) setDialect(c, dialect);
}

class Expander {
 public:
  Expander(ExpandResult& result, const std::map<std::string, std::string>& defines)
      : result_(result), params_(defines) {}

  void expandChildren(XmlNode& parent, std::vector<fs::path>& includeStack) {
    std::vector<XmlNode> out;
    for (auto& child : parent.children) {
      substitute(child);
      if (child.tag == "default") {
        params_.try_emplace(requireAttribute(child, "name"), requireAttribute(child, "value"));
      } else if (child.tag == "path") {
        result_.resolver.addDirectory(requireAttribute(child, "value"));
      } else if (child.tag == "alias") {
        result_.aliases[requireAttribute(child, "as")] = requireAttribute(child, "id");
      } else if (child.tag == "include") {
        include(child, out, includeStack);
      } else {
        expandChildren(child, includeStack);
        out.push_back(std::move(child));
      }
    }
    parent.children = std::move(out);
  }

 private:
  void substitute(XmlNode& node) {
    for (auto& [key, value] : node.attributes) {
      if (value.find('$') == std::string::npos) continue;
      try {
        value = substituteParameters(value, params_, &used_);
      } catch (const Error& e) {
        throw sceneError(node, e.what());
      }
    }
  }

  void include(const XmlNode& node, std::vector<XmlNode>& out, std::vector<fs::path>& includeStack) {
    const std::string& name = requireAttribute(node, "filename");
    auto file = result_.resolver.resolve(name);
    if (!file)
      throw sceneError(node, str("included file \"", name, "\" not found (looked in: ", result_.resolver.describe(), ")"));
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(*file, ec);
    for (const auto& open : includeStack)
      if (open == canonical)
        throw sceneError(node, str("file \"", name, "\" includes itself (include cycle)"));
    XmlNode included = readXmlFile(*file);
    result_.sources.add(included.source);
    if (included.dialect == UnknownDialect) setDialect(included, node.dialect);
    includeStack.push_back(canonical);
    if (included.tag == "scene") {
      expandChildren(included, includeStack);
      for (auto& c : included.children) out.push_back(std::move(c));
    } else {
      // A fragment whose root is a single object or value: expand it as if it were wrapped.
      XmlNode wrapper;
      wrapper.children.push_back(std::move(included));
      expandChildren(wrapper, includeStack);
      for (auto& c : wrapper.children) out.push_back(std::move(c));
    }
    includeStack.pop_back();
  }

  ExpandResult& result_;

 public:
  /// -D values and <default>s, by name.
  std::map<std::string, std::string> params_;
  /// Names any `$name` referred to, -D or <default>.
  std::set<std::string> used_;
};

}  // namespace

std::string substituteParameters(const std::string& text, const std::map<std::string, std::string>& params,
                                 std::set<std::string>* used) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    if (text[i] != '$') {
      out += text[i++];
      continue;
    }
    size_t end = i + 1;
    while (end < text.size() && isNameChar(text[end])) ++end;
    std::string name = text.substr(i + 1, end - i - 1);
    if (name.empty()) throw Error(str("'$' must be followed by a parameter name in '", text, "'"));
    auto it = params.find(name);
    if (it == params.end())
      throw Error(str("undefined parameter \"$", name, "\" (declare it with <default name=\"", name,
                      "\" value=\"...\"/> or pass -D ", name, "=...)"));
    out += it->second;
    if (used) used->insert(name);
    i = end;
  }
  return out;
}

ExpandResult expandDirectives(XmlNode& root, const fs::path& sceneDir, const std::map<std::string, std::string>& defines) {
  ExpandResult result{FileResolver(sceneDir), {}, {}};
  result.sources.add(root.source);
  if (root.dialect == UnknownDialect) setDialect(root, 3);
  Expander expander(result, defines);
  std::vector<fs::path> includeStack;
  if (root.source) {
    std::error_code ec;
    fs::path self = fs::weakly_canonical(root.source->file, ec);
    if (!ec && fs::exists(self)) includeStack.push_back(self);
  }
  // The root's own attributes may use -D parameters too.
  XmlNode wrapper;
  wrapper.children.push_back(std::move(root));
  expander.expandChildren(wrapper, includeStack);
  if (wrapper.children.size() != 1)
    throw Error("the scene's root element must be an object, not a directive such as <include> or <default>");
  root = std::move(wrapper.children.front());
  for (const auto& [name, value] : defines)
    if (!expander.used_.count(name)) result.unusedDefines.push_back(name);
  std::set<std::string> names = expander.used_;
  for (const auto& [name, value] : expander.params_)
    if (!defines.count(name)) names.insert(name);
  result.parameterNames.assign(names.begin(), names.end());
  return result;
}

}  // namespace femto::xml

