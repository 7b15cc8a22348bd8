#pragma once
#include <string>
#include <system_error>
#include <unistd.h>

#include <femto/base/error.h>
#include <femto/base/temp_files.h>

namespace femto {

template <typename Writer>
void writeAtomically(const std::filesystem::path& path, Writer&& writer) {
  namespace fs = std::filesystem;
  fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  fs::create_directories(dir, ec);
  // Keep the real extension last: image libraries pick the format from it.
  fs::path tmp = dir / (".tmp-" + std::to_string(::getpid()) + "-" + path.filename().string());
  TempFileGuard guard(tmp);  // a signal that ends the process removes it too
  try {
    writer(tmp);
  } catch (const Error& e) {
    fs::remove(tmp, ec);
    // Libraries name the file they were given: say the path the user gave.
    std::string message = e.what();
    const std::string hidden = tmp.string(), shown = path.string();
    for (size_t at = message.find(hidden); at != std::string::npos; at = message.find(hidden, at + shown.size()))
      message.replace(at, hidden.size(), shown);
    throw Error(message);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw Error(str("cannot write \"", path.string(), "\": ", ec.message()));
  }
}

}  // namespace femto
