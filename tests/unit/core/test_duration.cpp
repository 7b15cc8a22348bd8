// parseDuration: the time limit as people type it.
#include <gtest/gtest.h>

#include <femto/base/error.h>
#include <femto/core/duration.h>

namespace femto {
namespace {

TEST(Duration, ReadsSecondsMinutesAndHours) {
  EXPECT_DOUBLE_EQ(parseDuration("30s"), 30.0);
  EXPECT_DOUBLE_EQ(parseDuration("90"), 90.0);
  EXPECT_DOUBLE_EQ(parseDuration("0.5"), 0.5);
  EXPECT_DOUBLE_EQ(parseDuration("5m"), 300.0);
  EXPECT_DOUBLE_EQ(parseDuration("1.5h"), 5400.0);
}

TEST(Duration, RefusesWhatIsNotAPositiveDuration) {
  for (const char* bad : {"", "s", "abc", "0", "-3s", "3 s", "3x", "inf", "nan", "1e400"}) {
    try {
      parseDuration(bad);
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("got \"") + bad + "\""), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("such as 30s, 5m"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace femto
