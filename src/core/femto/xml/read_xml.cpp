#include "read_xml.h"

#include <cctype>
#include <fstream>
#include <sstream>

#include <tinyxml2.h>

#include "scene_error.h"

namespace femto::xml {
namespace {

XmlNode convert(const tinyxml2::XMLElement& element, const std::shared_ptr<const SourceText>& source, int dialect) {
  XmlNode node;
  node.tag = element.Name();
  node.location = SourceLocation{source->file, element.GetLineNum()};
  node.source = source;
  node.dialect = dialect;
  for (const tinyxml2::XMLAttribute* a = element.FirstAttribute(); a; a = a->Next())
    node.attributes.emplace_back(a->Name(), a->Value());
  for (const tinyxml2::XMLElement* c = element.FirstChildElement(); c; c = c->NextSiblingElement())
    node.children.push_back(convert(*c, source, dialect));
  return node;
}

/// tinyxml2's error as a phrase: its ErrorStr() reads "Error=NAME ErrorID=N
/// (0xN) Line number=L: detail"; keep a readable reason and the detail.
std::string describeXmlError(const tinyxml2::XMLDocument& doc) {
  std::string reason;
  switch (doc.ErrorID()) {
    case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT: reason = "an element is not closed, or closed by the wrong tag"; break;
    case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE: reason = "cannot read an attribute"; break;
    case tinyxml2::XML_ERROR_PARSING_ELEMENT: reason = "cannot read an element"; break;
    case tinyxml2::XML_ERROR_EMPTY_DOCUMENT: reason = "the document is empty"; break;
    default: reason = doc.ErrorName(); break;
  }
  std::string full = doc.ErrorStr() ? doc.ErrorStr() : "";
  size_t detail = full.find(": ", full.find("Line number="));
  if (full.find("Line number=") != std::string::npos && detail != std::string::npos && detail + 2 < full.size())
    reason += " (" + full.substr(detail + 2) + ")";
  return reason;
}

}  // namespace

int dialectOf(const std::string& version) {
  size_t digits = 0;
  while (digits < version.size() && std::isdigit(static_cast<unsigned char>(version[digits]))) ++digits;
  if (digits == 0 || digits > 4 || (digits < version.size() && version[digits] != '.'))
    throw Error(str("expected a version like \"3.0.0\", got '", version, "'"));
  return std::stoi(version.substr(0, digits));
}

XmlNode readXmlString(const std::string& text, const std::string& fileName) {
  auto source = SourceText::fromString(fileName, text);
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS) {
    int line = doc.ErrorLineNum();
    throw sceneError(SourceLocation{fileName, line}, source->line(line), str("malformed XML: ", describeXmlError(doc)));
  }
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root) throw Error(SourceLocation{fileName, 1}, "malformed XML: the file has no root element");
  int dialect = UnknownDialect;
  if (const char* version = root->Attribute("version")) {
    try {
      dialect = dialectOf(version);
    } catch (const Error& e) {
      throw sceneError(SourceLocation{fileName, root->GetLineNum()}, source->line(root->GetLineNum()), e.what());
    }
  }
  return convert(*root, source, dialect);
}

XmlNode readXmlFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(str("cannot open scene file \"", file.string(), "\""));
  std::ostringstream text;
  text << in.rdbuf();
  return readXmlString(text.str(), file.string());
}

}  // namespace femto::xml
