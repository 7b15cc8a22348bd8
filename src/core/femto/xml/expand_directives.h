#pragma once
// Parse stage 2: expand <include>, <default>, $name, <path> and <alias>, so
// later stages see one tree of objects and values only.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "file_resolver.h"
#include "scene_error.h"
#include "xml_node.h"

namespace femto::xml {

struct ExpandResult {
  /// Where relative file names resolve (scene folder, then <path> dirs).
  FileResolver resolver;
  /// <alias id="a" as="b"/>: b -> a.
  std::map<std::string, std::string> aliases;
  /// Every file read (the main one and includes), for echoing lines.
  SourceRegistry sources;
  /// -D names no `$name` of the expanded scene referred to: they changed
  /// nothing (a misspelt name, or one only an unselected include uses).
  std::vector<std::string> unusedDefines;
  /// The names the scene refers to (`$name`) or gives a <default> for: the
  /// candidates of an unused -D's "did you mean" hint.
  std::vector<std::string> parameterNames;
};

/// Expand the directives in `root` in document order:
///  - `defines` (-D name=value) are set first; <default name value> sets a
///    parameter only when nothing set it before;
///  - `$name` in any attribute is replaced (an undefined name is an error);
///  - <include filename> splices the children of the included <scene> (or the
///    included root element itself) in place; files resolve against the main
///    scene's folder and <path> dirs; a file including itself (directly or not) is an error;
///  - <path value> adds a search directory; <alias id as> records an alias.
/// Included files without version="" take the dialect of the including file;
/// the main file without one is Mitsuba 3 (dialect 3).
ExpandResult expandDirectives(XmlNode& root, const std::filesystem::path& sceneDir,
                              const std::map<std::string, std::string>& defines);

/// Replace every $name in `text` (names are [A-Za-z0-9_]+); throws for undefined names.
/// Each name substituted is added to `used` when given.
std::string substituteParameters(const std::string& text, const std::map<std::string, std::string>& params,
                                 std::set<std::string>* used = nullptr);

}  // namespace femto::xml
