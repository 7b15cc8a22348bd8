#pragma once
// Parse stage 5, values: one value element (<float>, <rgb>, <transform>, ...)
// into a typed Properties entry that remembers its file:line.
#include <femto/core/properties.h>

#include "file_resolver.h"
#include "xml_node.h"

namespace femto::xml {

/// Is `tag` a value element (not an object or a directive)?
bool isValueTag(const std::string& tag);

/// <transform>: its children (translate, rotate, scale, matrix, lookat/lookAt)
/// composed in document order, each applied after the previous (T = op * T).
Transform parseTransform(const XmlNode& node);

/// Add the value element `node` (a child of an object) to `props` under its
/// name="". Strings named "filename" become absolute paths through `resolver`
/// (a missing file is an error). Errors name `node`'s file:line and echo it.
void addValueProperty(Properties& props, const XmlNode& node, const FileResolver& resolver);

}  // namespace femto::xml
