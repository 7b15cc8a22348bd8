#pragma once
// One exception type for every user-facing failure. Messages are complete
// sentences; scene errors carry the file and line they refer to.
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace femto {

/// Concatenate any streamable values into a string: str("bins=", n).
template <typename... Args>
std::string str(Args&&... args) {
  std::ostringstream os;
  (os << ... << std::forward<Args>(args));
  return os.str();
}

/// Where something was written: a scene file and a 1-based line (0 = unknown).
struct SourceLocation {
  std::string file;
  int line = 0;
  bool known() const { return !file.empty(); }
  /// "file:line" or "" when unknown.
  std::string toString() const { return file.empty() ? std::string() : str(file, ':', line); }
};

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  /// "file:line: message" when `where` is known.
  Error(const SourceLocation& where, const std::string& message)
      : std::runtime_error(where.known() ? where.toString() + ": " + message : message), where_(where) {}
  const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

}  // namespace femto
