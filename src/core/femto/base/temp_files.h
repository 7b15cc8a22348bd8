#pragma once
// Temporary files that must not outlive the process. Outputs are written
// under a hidden temporary name and renamed when complete (writeAtomically);
// a destructor removes the temporary after an exception, but a signal that
// kills the process runs no destructor. Registered temporaries are removed by
// removeTempFilesNow(), which a signal handler may call.
#include <filesystem>

namespace femto {

/// Registers `path` for the lifetime of the guard (or until release()).
class TempFileGuard {
 public:
  explicit TempFileGuard(const std::filesystem::path& path);
  ~TempFileGuard() { release(); }
  TempFileGuard(const TempFileGuard&) = delete;
  TempFileGuard& operator=(const TempFileGuard&) = delete;
  /// The file was renamed or removed: stop tracking it.
  void release();

 private:
  int slot_ = -1;  // -1: not registered (released, or every slot was taken)
};

/// Unlink every registered temporary. Async-signal-safe (unlink(2) on paths
/// stored in fixed slots; no allocation, no lock).
void removeTempFilesNow() noexcept;

}  // namespace femto
