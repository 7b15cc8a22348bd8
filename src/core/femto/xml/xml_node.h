#pragma once
// Internal to the loader: the scene file as a tree of elements that remember
// where they were written, so every later stage can name file:line and echo
// the offending line.
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <femto/base/error.h>

namespace femto::xml {

/// The text of one scene file, kept for echoing lines in messages.
struct SourceText {
  std::string file;  // as shown in messages
  std::vector<std::string> lines;
  /// Line `n` (1-based) without trailing '\r', or "" when out of range.
  std::string line(int n) const;
  static std::shared_ptr<const SourceText> fromString(std::string file, const std::string& text);
};

/// Dialect of a file: the major version of its root's version="" attribute.
/// Mitsuba 0.4-0.6 files are 0; Mitsuba 3 files are 2 or 3 (-1 = not given).
inline constexpr int UnknownDialect = -1;

struct XmlNode {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attributes;  // document order
  std::vector<XmlNode> children;
  SourceLocation location;
  std::shared_ptr<const SourceText> source;
  int dialect = UnknownDialect;
  /// For <ref>: the object node it names (set by resolveReferences).
  const XmlNode* target = nullptr;

  const std::string* attribute(std::string_view name) const;
  std::string attributeOr(std::string_view name, const std::string& def) const;
  void setAttribute(const std::string& name, std::string value);
  /// The raw text of the line this element starts on.
  std::string lineText() const { return source ? source->line(location.line) : std::string(); }
};

}  // namespace femto::xml
