#include "scene_error.h"

namespace femto::xml {

std::string withEchoedLine(const std::string& message, const std::string& lineText) {
  size_t begin = lineText.find_first_not_of(" \t");
  if (begin == std::string::npos) return message;
  size_t end = lineText.find_last_not_of(" \t\r");
  return message + "\n    " + lineText.substr(begin, end - begin + 1);
}

Error sceneError(const SourceLocation& where, const std::string& lineText, const std::string& message) {
  return Error(where, withEchoedLine(message, lineText));
}

Error sceneError(const XmlNode& node, const std::string& message) {
  return sceneError(node.location, node.lineText(), message);
}

void SourceRegistry::add(std::shared_ptr<const SourceText> source) {
  if (source) files_[source->file] = std::move(source);
}

std::string SourceRegistry::lineText(const SourceLocation& where) const {
  auto it = files_.find(where.file);
  return it == files_.end() ? std::string() : it->second->line(where.line);
}

Error SourceRegistry::addEcho(const Error& e, const XmlNode& fallback) const {
  std::string message = e.what();
  if (message.find('\n') != std::string::npos) return e;  // already echoed
  if (!e.where().known()) return sceneError(fallback, message);
  // Error() prefixed "file:line: "; rebuild the message around the echo.
  std::string prefix = e.where().toString() + ": ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  return sceneError(e.where(), lineText(e.where()), message);
}

}  // namespace femto::xml
