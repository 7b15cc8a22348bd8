#include <femto/core/resources.h>

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>

#include <femto/base/error.h>
#include <femto/core/log.h>

namespace femto {

std::string formatBytes(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 5) bytes /= 1024.0, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

namespace {

/// A number read from a cgroup file ("max" or absent: nullopt).
std::optional<uint64_t> cgroupNumber(const char* path) {
  std::ifstream in(path);
  uint64_t value = 0;
  if (in >> value) return value;
  return std::nullopt;
}

}  // namespace

std::optional<uint64_t> availableMemoryBytes() {
  std::optional<uint64_t> available;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") {
      available = kib * 1024;
      break;
    }
  // A container's limit (cgroup v2, then v1) may be far below the machine's.
  for (auto [limitFile, usageFile] : {std::pair{"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory.current"},
                                      std::pair{"/sys/fs/cgroup/memory/memory.limit_in_bytes",
                                                "/sys/fs/cgroup/memory/memory.usage_in_bytes"}}) {
    const std::optional<uint64_t> limit = cgroupNumber(limitFile), usage = cgroupNumber(usageFile);
    if (!limit || !usage) continue;
    const uint64_t left = *limit > *usage ? *limit - *usage : 0;
    available = available ? std::min(*available, left) : left;
    break;
  }
  return available;
}

std::optional<uint64_t> freeDiskBytes(const std::filesystem::path& path) {
  std::filesystem::path probe = std::filesystem::absolute(path);
  std::error_code ec;
  while (!probe.empty() && !std::filesystem::exists(probe, ec)) {
    if (probe == probe.parent_path()) break;
    probe = probe.parent_path();
  }
  struct statvfs fs {};
  if (::statvfs(probe.c_str(), &fs) != 0) return std::nullopt;
  return uint64_t(fs.f_bavail) * uint64_t(fs.f_frsize);
}

void requireMemory(double bytes, const std::string& what, const std::string& advice) {
  std::optional<uint64_t> available = availableMemoryBytes();
  if (!available || bytes <= double(*available)) return;
  throw Error(str(what, " needs ", formatBytes(bytes), " of memory, but only ", formatBytes(double(*available)),
                  " is available: ", advice));
}

std::string largeOutputNotice(double bytes, std::optional<uint64_t> freeBytes, const std::string& what) {
  const bool large = bytes >= LargeOutputBytes || (freeBytes && bytes >= LargeOutputFreeFraction * double(*freeBytes));
  if (!large) return "";
  return str(what, " will take ", formatBytes(bytes), " on disk",
             freeBytes ? str(" (", formatBytes(double(*freeBytes)), " free there)") : std::string());
}

void requireDisk(const std::filesystem::path& path, double bytes, const std::string& what, const std::string& advice) {
  std::optional<uint64_t> free = freeDiskBytes(path);
  if (std::string notice = largeOutputNotice(bytes, free, what); !notice.empty() && (!free || bytes <= double(*free)))
    logInfo(notice, ": \"", path.string(), "\"");
  if (!free || bytes <= double(*free)) return;
  throw Error(str(what, " needs ", formatBytes(bytes), " on disk, but the file system of \"", path.string(),
                  "\" has only ", formatBytes(double(*free)), " free: ", advice));
}

void requireWritableFolder(const std::filesystem::path& folder, const std::filesystem::path& output, bool makeMissing) {
  namespace fs = std::filesystem;
  auto refuse = [&](const fs::path& where, const std::string& why) {
    throw Error(str("cannot write \"", output.string(), "\": the folder \"", where.string(), "\" ", why));
  };
  fs::path probeIn = folder.empty() ? fs::path(".") : folder;
  std::error_code ec;
  if (fs::exists(probeIn, ec) && !fs::is_directory(probeIn, ec)) refuse(probeIn, "is a file, not a folder");
  if (!fs::is_directory(probeIn, ec)) {
    if (makeMissing) {
      if (!fs::create_directories(probeIn, ec) && !fs::is_directory(probeIn))
        refuse(probeIn, str("cannot be made (", ec ? ec.message() : std::string("not a folder"), ")"));
    } else {
      // Made only when written: probe the nearest existing parent instead.
      while (!probeIn.empty() && !fs::exists(probeIn, ec)) probeIn = probeIn.parent_path();
      if (probeIn.empty()) probeIn = ".";
      if (!fs::is_directory(probeIn, ec)) refuse(probeIn, "is a file, not a folder");
    }
  }
  fs::path probe = probeIn / (".femto-write-test-" + std::to_string(::getpid()));
  int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) refuse(probeIn, str("is not writable (", std::strerror(errno), ")"));
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace femto
