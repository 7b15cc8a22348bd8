// ProgressReporter draws only on a terminal: under ctest stderr is a pipe, so
// nothing may be written however often it is updated.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <thread>
#include <vector>

#include <femto/core/progress.h>

namespace femto {
namespace {

TEST(ProgressReporter, SilentWhenStderrIsNotATerminal) {
  if (isatty(STDERR_FILENO)) GTEST_SKIP() << "stderr is a terminal";
  testing::internal::CaptureStderr();
  {
    ProgressReporter progress("render", 4000);
    std::vector<std::thread> workers;
    for (int t = 0; t < 4; ++t)
      workers.emplace_back([&] {
        for (int i = 0; i < 1000; ++i) progress.update(1);
      });
    for (auto& w : workers) w.join();
    progress.finish();
    progress.finish();  // idempotent
    EXPECT_GE(progress.elapsedSeconds(), 0.0);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

// The callback gets what the bar shows, terminal or not, bar enabled or not:
// a throttled report while running (fraction done, an ETA extrapolated from
// the time so far) and a last one marked finished.
TEST(ProgressReporter, CallbackGetsFractionEtaAndTheFinalReport) {
  std::vector<ProgressState> reports;
  {
    ProgressReporter progress("render", 4, /*enabled=*/false, [&](const ProgressState& s) { reports.push_back(s); });
    std::this_thread::sleep_for(std::chrono::milliseconds(120));  // past the redraw interval
    progress.update(1);
    progress.finish();
    progress.finish();  // reported once
  }
  ASSERT_EQ(reports.size(), 2u);
  EXPECT_EQ(reports[0].label, "render");
  EXPECT_DOUBLE_EQ(reports[0].fraction, 0.25);
  EXPECT_FALSE(reports[0].finished);
  // One quarter took elapsed seconds: three more quarters take three times that.
  EXPECT_NEAR(reports[0].etaSeconds, 3 * reports[0].elapsedSeconds, 1e-9);
  EXPECT_GE(reports[0].elapsedSeconds, 0.1);
  EXPECT_TRUE(reports[1].finished);
  EXPECT_DOUBLE_EQ(reports[1].fraction, 0.25);
  EXPECT_LT(reports[1].etaSeconds, 0.0);
}

}  // namespace
}  // namespace femto
