// Registered temporaries are what a signal handler removes: removeTempFilesNow
// unlinks exactly the files whose guards are alive.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <femto/base/temp_files.h>

namespace femto {
namespace {

std::filesystem::path touch(const std::string& name) {
  std::filesystem::path path = std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::ofstream(path) << "x";
  return path;
}

TEST(TempFiles, RemovesRegisteredFilesOnly) {
  std::filesystem::path live = touch("femto-temp-live"), released = touch("femto-temp-released"),
                        never = touch("femto-temp-never");
  TempFileGuard liveGuard(live);
  {
    TempFileGuard releasedGuard(released);
    releasedGuard.release();
  }
  removeTempFilesNow();
  EXPECT_FALSE(std::filesystem::exists(live));
  EXPECT_TRUE(std::filesystem::exists(released));
  EXPECT_TRUE(std::filesystem::exists(never));
  std::filesystem::remove(released);
  std::filesystem::remove(never);
}

TEST(TempFiles, AGuardOutOfScopeIsForgotten) {
  std::filesystem::path path = touch("femto-temp-scoped");
  { TempFileGuard guard(path); }
  removeTempFilesNow();
  EXPECT_TRUE(std::filesystem::exists(path));
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace femto
