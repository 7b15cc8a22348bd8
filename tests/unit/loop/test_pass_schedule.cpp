// PassSchedule: how many passes a render makes, by count or by time budget,
// on a clock the test moves by hand (no test here reads a real clock).
#include <gtest/gtest.h>

#include <femto/base/error.h>
#include <femto/loop/pass_schedule.h>

namespace femto {
namespace {

/// Passes the schedule starts when each pass takes `passSeconds[i]` on a fake clock.
int passesStarted(PassSchedule& schedule, double& clock, const std::vector<double>& passSeconds) {
  int pass = 0;
  while (schedule.startPass(pass)) {
    clock += passSeconds.at(size_t(pass));
    ++pass;
  }
  return pass;
}

TEST(PassSchedule, WithoutLimitRendersTheIntegratorsCountOrTheGivenOne) {
  double clock = 0.0;
  RenderOptions options;
  PassSchedule own(options, 4, [&] { return clock; });
  EXPECT_EQ(own.expectedPasses(), 4);
  EXPECT_EQ(passesStarted(own, clock, std::vector<double>(10, 100.0)), 4);  // time plays no part
  EXPECT_FALSE(own.limitReached());
  options.passes = 2;
  PassSchedule given(options, 4, [&] { return clock; });
  EXPECT_EQ(passesStarted(given, clock, std::vector<double>(10, 1.0)), 2);
  PassSchedule zero(RenderOptions{}, 0, [&] { return clock; });  // an integrator saying 0 still renders one
  EXPECT_EQ(passesStarted(zero, clock, std::vector<double>(10, 1.0)), 1);
}

TEST(PassSchedule, TimeLimitStartsAPassOnlyWhenTheLastPassesTimeStillFits) {
  double clock = 50.0;  // any origin
  RenderOptions options;
  options.timeLimit = 10.0;
  PassSchedule schedule(options, 4, [&] { return clock; });  // the integrator's 4 do not cap it
  // Passes of 3 s: after 3 passes 9 s are spent and a 4th would end at 12 > 10.
  EXPECT_EQ(passesStarted(schedule, clock, std::vector<double>(10, 3.0)), 3);
  EXPECT_TRUE(schedule.limitReached());
  EXPECT_DOUBLE_EQ(schedule.spent(), 9.0);
}

TEST(PassSchedule, TimeLimitPredictsFromTheLastPassNotTheFirst) {
  // A first pass that costs more (transient_beams derives its radii in it):
  // 4 s, then 1 s each. After pass k (k >= 1) 4 + (k - 1) s are spent; pass k
  // starts while that + 1 <= 10, i.e. up to k = 6: 7 passes, 10 s.
  double clock = 0.0;
  RenderOptions options;
  options.timeLimit = 10.0;
  PassSchedule schedule(options, 1, [&] { return clock; });
  EXPECT_EQ(passesStarted(schedule, clock, {4, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}), 7);
  EXPECT_DOUBLE_EQ(clock, 10.0);
}

TEST(PassSchedule, FirstPassAlwaysRendersAndPassesCapTheBudget) {
  double clock = 0.0;
  RenderOptions options;
  options.timeLimit = 1.0;
  PassSchedule slow(options, 1, [&] { return clock; });
  EXPECT_EQ(passesStarted(slow, clock, std::vector<double>(4, 5.0)), 1);  // over budget, but a valid result
  EXPECT_TRUE(slow.limitReached());
  options.timeLimit = 100.0;
  options.passes = 3;
  PassSchedule capped(options, 1, [&] { return clock; });
  EXPECT_EQ(passesStarted(capped, clock, std::vector<double>(10, 1.0)), 3);
  EXPECT_FALSE(capped.limitReached());
}

TEST(PassSchedule, ExpectedPassesFollowTheTimeLeft) {
  double clock = 0.0;
  RenderOptions options;
  options.timeLimit = 10.0;
  PassSchedule schedule(options, 1, [&] { return clock; });
  ASSERT_TRUE(schedule.startPass(0));
  clock += 2.0;
  ASSERT_TRUE(schedule.startPass(1));
  // 2 s per pass, 8 s left: this pass and 3 more, 5 in all.
  EXPECT_EQ(schedule.expectedPasses(), 5);
}

TEST(PassSchedule, RefusesABadLimit) {
  RenderOptions options;
  options.timeLimit = -1.0;
  EXPECT_THROW(PassSchedule(options, 1, [] { return 0.0; }), Error);
}

}  // namespace
}  // namespace femto
