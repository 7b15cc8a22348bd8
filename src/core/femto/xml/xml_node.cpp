#include "xml_node.h"

#include <sstream>

namespace femto::xml {

std::string SourceText::line(int n) const {
  if (n < 1 || size_t(n) > lines.size()) return "";
  std::string s = lines[size_t(n) - 1];
  if (!s.empty() && s.back() == '\r') s.pop_back();
  return s;
}

std::shared_ptr<const SourceText> SourceText::fromString(std::string file, const std::string& text) {
  auto src = std::make_shared<SourceText>();
  src->file = std::move(file);
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) src->lines.push_back(line);
  return src;
}

const std::string* XmlNode::attribute(std::string_view name) const {
  for (const auto& [key, value] : attributes)
    if (key == name) return &value;
  return nullptr;
}

std::string XmlNode::attributeOr(std::string_view name, const std::string& def) const {
  const std::string* v = attribute(name);
  return v ? *v : def;
}

void XmlNode::setAttribute(const std::string& name, std::string value) {
  for (auto& [key, v] : attributes)
    if (key == name) {
      v = std::move(value);
      return;
    }
  attributes.emplace_back(name, std::move(value));
}

}  // namespace femto::xml
