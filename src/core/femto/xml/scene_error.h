#pragma once
// Internal to the loader: every scene error reads
//   FILE:LINE: message
//       <the offending line of the file>
#include <map>
#include <memory>
#include <string>

#include "xml_node.h"

namespace femto::xml {

/// The message with the offending line echoed below it (indented).
std::string withEchoedLine(const std::string& message, const std::string& lineText);
/// An error at `node`'s file:line with its line echoed.
Error sceneError(const XmlNode& node, const std::string& message);
Error sceneError(const SourceLocation& where, const std::string& lineText, const std::string& message);

/// The attribute `name` of `node`; its absence is an error at the node.
const std::string& requireAttribute(const XmlNode& node, const char* name);
/// e.what() without the "file:line: " prefix Error(where, ...) added.
std::string messageWithoutLocation(const Error& e);
/// Has the message already got its line echoed (so it must not be wrapped again)?
bool isEchoed(const Error& e);

/// All files read for one load, so errors raised later (e.g. by a plugin
/// constructor, which only knows a SourceLocation) can echo their line.
class SourceRegistry {
 public:
  void add(std::shared_ptr<const SourceText> source);
  std::string lineText(const SourceLocation& where) const;
  /// `e` with its line echoed, if it names a location and has no echo yet;
  /// errors without a location are placed at `fallback`.
  Error addEcho(const Error& e, const XmlNode& fallback) const;

 private:
  std::map<std::string, std::shared_ptr<const SourceText>> files_;
};

}  // namespace femto::xml
