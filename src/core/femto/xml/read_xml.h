#pragma once
// Parse stage 1: XML text -> XmlNode tree (elements only; comments and text
// dropped), every node knowing its file, line and dialect.
#include <filesystem>
#include <string>

#include "xml_node.h"

namespace femto::xml {

/// Parse `text`; `fileName` is used in messages. Malformed XML throws
/// "file:line: malformed XML: <tinyxml2's reason>" with the line echoed.
XmlNode readXmlString(const std::string& text, const std::string& fileName);
/// Read and parse a file; a missing or unreadable file is an error.
XmlNode readXmlFile(const std::filesystem::path& file);

/// Major version of a version="" attribute ("0.5.0" -> 0, "3.0.0" -> 3); throws on malformed text.
int dialectOf(const std::string& version);

}  // namespace femto::xml
