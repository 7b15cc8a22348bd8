// Resource checks refuse what cannot fit, naming the sizes, and pass what can.
#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <string>

#include <femto/base/error.h>
#include <femto/core/resources.h>

namespace femto {
namespace {

TEST(Resources, FormatsBytesInBinaryUnits) {
  EXPECT_EQ(formatBytes(100), "100 B");
  EXPECT_EQ(formatBytes(1536), "1.5 KiB");
  EXPECT_EQ(formatBytes(3.0 * (1ull << 30)), "3.0 GiB");
}

/// A number in a file (nullopt: absent or not a number, as cgroup's "max").
std::optional<uint64_t> numberIn(const char* path) {
  std::ifstream in(path);
  uint64_t value = 0;
  if (in >> value) return value;
  return std::nullopt;
}

TEST(Resources, AvailableMemoryStaysWithinTheMachinesAndTheCgroupsLimits) {
  std::optional<uint64_t> available = availableMemoryBytes();
  ASSERT_TRUE(available.has_value());
  std::ifstream meminfo("/proc/meminfo");
  std::string key, unit;
  uint64_t kib = 0, memAvailable = 0;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") memAvailable = kib * 1024;
  // Both read at slightly different moments: allow for the memory that moved in between.
  const uint64_t slack = uint64_t(64) << 20;
  EXPECT_LE(*available, memAvailable + slack);
  const std::optional<uint64_t> limit = numberIn("/sys/fs/cgroup/memory.max"),
                                usage = numberIn("/sys/fs/cgroup/memory.current");
  if (limit && usage) EXPECT_LE(*available, (*limit > *usage ? *limit - *usage : 0) + slack);
}

TEST(Resources, MemoryBeyondWhatIsAvailableIsRefusedWithItsSize) {
  std::optional<uint64_t> available = availableMemoryBytes();
  ASSERT_TRUE(available.has_value()) << "/proc/meminfo has no MemAvailable";
  EXPECT_NO_THROW(requireMemory(1024.0, "a small buffer", "none"));
  try {
    requireMemory(4.0 * double(*available), "the test image", "make it smaller");
    FAIL() << "four times the available memory was accepted";
  } catch (const Error& e) {
    std::string message = e.what();
    EXPECT_NE(message.find("the test image needs"), std::string::npos) << message;
    EXPECT_NE(message.find("GiB"), std::string::npos) << message;
    EXPECT_NE(message.find("make it smaller"), std::string::npos) << message;
  }
}

TEST(Resources, DiskBeyondTheFreeSpaceIsRefusedNamingThePath) {
  std::optional<uint64_t> free = freeDiskBytes("/tmp/femto-not-yet-made/out.npy");
  ASSERT_TRUE(free.has_value()) << "statvfs failed on /tmp (the nearest existing parent)";
  EXPECT_NO_THROW(requireDisk("/tmp/out.npy", 1.0, "a tiny file", "none"));
  try {
    requireDisk("/tmp/out.npy", 2.0 * double(*free) + 1.0, "the volume", "use fewer bins");
    FAIL() << "twice the free space was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("\"/tmp/out.npy\""), std::string::npos) << e.what();
  }
}

TEST(Resources, LargeOutputsAreAnnouncedWithTheirSize) {
  const double GiB = 1024.0 * 1024.0 * 1024.0;
  const uint64_t terabyte = uint64_t(1) << 40;
  // Below both thresholds: nothing.
  EXPECT_EQ(largeOutputNotice(1.0 * GiB, terabyte, "the volume"), "");
  // 4 GiB or more, whatever the free space (known or not).
  EXPECT_EQ(largeOutputNotice(LargeOutputBytes, terabyte, "the volume"), "the volume will take 4.0 GiB on disk (1.0 TiB free there)");
  EXPECT_EQ(largeOutputNotice(LargeOutputBytes, std::nullopt, "the volume"), "the volume will take 4.0 GiB on disk");
  // 10 % of the free space, however small.
  EXPECT_EQ(largeOutputNotice(0.099 * 1000.0, uint64_t(1000), "v"), "");
  EXPECT_NE(largeOutputNotice(0.1 * 1000.0, uint64_t(1000), "v"), "");
}

}  // namespace
}  // namespace femto
