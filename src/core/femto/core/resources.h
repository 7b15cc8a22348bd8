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
/// /proc/meminfo); nullopt where unknown.
std::optional<uint64_t> availableMemoryBytes();

/// Free space for an unprivileged writer on the file system holding `path`
/// (or its nearest existing parent); nullopt where unknown.
std::optional<uint64_t> freeDiskBytes(const std::filesystem::path& path);

/// Throws an Error when `bytes` exceed the available memory:
/// "<what> needs <size> of memory, only <size> is available: <advice>".
void requireMemory(double bytes, const std::string& what, const std::string& advice);

/// Throws an Error when `bytes` exceed the free space where `path` goes.
void requireDisk(const std::filesystem::path& path, double bytes, const std::string& what, const std::string& advice);

}  // namespace femto
