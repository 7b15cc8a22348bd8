// ProgressReporter draws only on a terminal: under ctest stderr is a pipe, so
// nothing may be written however often it is updated.
#include <gtest/gtest.h>
#include <unistd.h>

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

}  // namespace
}  // namespace femto
