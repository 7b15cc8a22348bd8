// Resource checks refuse what cannot fit, naming the sizes, and pass what can.
#include <gtest/gtest.h>

#include <femto/base/error.h>
#include <femto/core/resources.h>

namespace femto {
namespace {

TEST(Resources, FormatsBytesInBinaryUnits) {
  EXPECT_EQ(formatBytes(100), "100 B");
  EXPECT_EQ(formatBytes(1536), "1.5 KiB");
  EXPECT_EQ(formatBytes(3.0 * (1ull << 30)), "3.0 GiB");
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

}  // namespace
}  // namespace femto
