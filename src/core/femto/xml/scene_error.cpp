#include "scene_error.h"

namespace femto::xml {

std::string withEchoedLine(const std::string& message, const std::string& lineText) {
  size_t begin = lineText.find_first_not_of(" \t");
  if (begin == std::string::npos) return message;
  size_t end = lineText.find_last_not_of(" \t\r");
  std::string line = lineText.substr(begin, end - begin + 1);
  // Sampled spectra and matrices make very long lines; the start locates the element.
  constexpr size_t MaxEcho = 160;
  if (line.size() > MaxEcho) line = line.substr(0, MaxEcho) + " ...";
  return message + "\n    " + line;
}

Error sceneError(const SourceLocation& where, const std::string& lineText, const std::string& message) {
  return Error(where, withEchoedLine(message, lineText));
}

Error sceneError(const XmlNode& node, const std::string& message) {
  return sceneError(node.location, node.lineText(), message);
}

const std::string& requireAttribute(const XmlNode& node, const char* name) {
  const std::string* v = node.attribute(name);
  if (!v) throw sceneError(node, str("<", node.tag, "> needs a ", name, "=\"...\" attribute"));
  return *v;
}

std::string messageWithoutLocation(const Error& e) {
  std::string message = e.what();
  std::string prefix = e.where().known() ? e.where().toString() + ": " : "";
  if (!prefix.empty() && message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  return message;
}

bool isEchoed(const Error& e) { return std::string(e.what()).find('\n') != std::string::npos; }

void SourceRegistry::add(std::shared_ptr<const SourceText> source) {
  if (source) files_[source->file] = std::move(source);
}

std::string SourceRegistry::lineText(const SourceLocation& where) const {
  auto it = files_.find(where.file);
  return it == files_.end() ? std::string() : it->second->line(where.line);
}

Error SourceRegistry::addEcho(const Error& e, const XmlNode& fallback) const {
  if (isEchoed(e)) return e;
  if (!e.where().known()) return sceneError(fallback, e.what());
  return sceneError(e.where(), lineText(e.where()), messageWithoutLocation(e));
}

}  // namespace femto::xml
