#pragma once
// Internal to the loader (and its tests): stages 1-4 run together, leaving a
// tree ready for ObjectBuilder (stage 5).
#include <filesystem>
#include <string>

#include <femto/xml/loader.h>

#include "build_objects.h"
#include "expand_directives.h"
#include "read_xml.h"
#include "resolve_references.h"
#include "upgrade_names.h"
#include "parse_values.h"
#include "value_properties.h"

namespace femto::xml {

struct ParsedScene {
  XmlNode root;
  ExpandResult expanded;
  ObjectIndex index;
};

/// Stages 2-4 on a tree from readXml*: directives, name upgrade, references.
/// Relative files resolve against `sceneDir`.
ParsedScene parseTree(XmlNode root, const std::filesystem::path& sceneDir, const LoadOptions& options);
/// Stages 1-4 on a string.
ParsedScene parseString(const std::string& xml, const std::filesystem::path& sceneDir, const LoadOptions& options,
                        const std::string& virtualName = "<string>");
/// Stages 1-4 on a file.
ParsedScene parseFile(const std::filesystem::path& file, const LoadOptions& options);

/// Stage 5 with a given factory (tests pass a double).
ObjectRef buildObject(const ParsedScene& parsed, const LoadOptions& options, ObjectFactory& factory);

}  // namespace femto::xml
