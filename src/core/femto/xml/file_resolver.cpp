#include "file_resolver.h"

namespace femto::xml {

namespace fs = std::filesystem;

void FileResolver::addDirectory(const fs::path& dir) {
  dirs_.push_back(dir.is_absolute() ? dir : sceneDir() / dir);
}

std::optional<fs::path> FileResolver::resolve(const std::string& name) const {
  fs::path p(name);
  std::error_code ec;
  if (p.is_absolute()) {
    if (fs::is_regular_file(p, ec)) return p.lexically_normal();
    return std::nullopt;
  }
  for (const auto& dir : dirs_) {
    fs::path candidate = fs::absolute(dir / p, ec).lexically_normal();
    if (!ec && fs::is_regular_file(candidate, ec)) return candidate;
  }
  return std::nullopt;
}

std::string FileResolver::describe() const {
  std::string out;
  for (const auto& dir : dirs_) out += (out.empty() ? "" : ", ") + (dir.empty() ? std::string(".") : dir.string());
  return out;
}

}  // namespace femto::xml
