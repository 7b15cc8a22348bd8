#pragma once
// Resources a render needs, checked before any work starts: a render refused
// at once with the sizes named beats a std::bad_alloc, an OOM kill or a full
// disk after hours of rendering.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace femto {

/// "3.2 GiB", "512 MiB", "12 KiB", "100 B".
std::string formatBytes(double bytes);

/// Memory the system can still give this process (MemAvailable of
/// /proc/meminfo, or less: what is left under the process's cgroup limit);
/// nullopt where unknown.
std::optional<uint64_t> availableMemoryBytes();

/// Free space for an unprivileged writer on the file system holding `path`
/// (or its nearest existing parent); nullopt where unknown.
std::optional<uint64_t> freeDiskBytes(const std::filesystem::path& path);

/// Throws an Error when `bytes` exceed the available memory:
/// "<what> needs <size> of memory, only <size> is available: <advice>".
void requireMemory(double bytes, const std::string& what, const std::string& advice);

/// Throws an Error when `bytes` exceed the free space where `path` goes.
void requireDisk(const std::filesystem::path& path, double bytes, const std::string& what, const std::string& advice);

/// Outputs this large are announced before the work starts.
constexpr double LargeOutputBytes = 4.0 * 1024 * 1024 * 1024;
constexpr double LargeOutputFreeFraction = 0.1;

/// "<what> will take <size> on disk (<free> free there)" when `bytes` reach
/// LargeOutputBytes or LargeOutputFreeFraction of `freeBytes` (when known);
/// otherwise "".
std::string largeOutputNotice(double bytes, std::optional<uint64_t> freeBytes, const std::string& what);

/// Throws an Error, naming `output` (the path as the user gave it), unless a
/// file can be made in `folder`: probes with a file of its own, which also
/// catches read-only and pseudo file systems (/proc) that permission bits do
/// not show. `makeMissing`: a missing folder is made first; otherwise it
/// passes when its nearest existing parent is writable.
void requireWritableFolder(const std::filesystem::path& folder, const std::filesystem::path& output, bool makeMissing);

}  // namespace femto
