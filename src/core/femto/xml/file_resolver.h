#pragma once
// Internal to the loader: relative file names resolve as in Mitsuba, against
// the MAIN scene file's folder first, then the <path> directories in the order given.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace femto::xml {

class FileResolver {
 public:
  explicit FileResolver(std::filesystem::path sceneDir) : dirs_{std::move(sceneDir)} {}
  /// <path value="..."/>: relative directories are taken from the scene folder.
  void addDirectory(const std::filesystem::path& dir);
  /// Absolute path of an existing file, or nullopt.
  std::optional<std::filesystem::path> resolve(const std::string& name) const;
  /// "a, b, c": the directories tried, for messages.
  std::string describe() const;
  const std::filesystem::path& sceneDir() const { return dirs_.front(); }

 private:
  std::vector<std::filesystem::path> dirs_;
};

}  // namespace femto::xml
