#pragma once
// How many passes a progressive render makes: a fixed count, or, under a time
// limit (`femto render --time-limit`, Mitsuba's `timeout`), as many whole
// passes as the budget holds. Only whole passes are rendered, so a
// time-limited render that reached N passes is bitwise the render asked for
// N passes (the passes' seeds and their running mean do not depend on how
// many follow): the time decides the count, never the values.
#include <functional>

#include <femto/render/integrator.h>

namespace femto {

/// Seconds on `clock` from an arbitrary origin (wall: steady clock; CPU: the
/// process's user + system time over all threads).
double clockSeconds(RenderClock clock);
/// "wall" / "cpu".
const char* clockName(RenderClock clock);

class PassSchedule {
 public:
  /// `integratorPasses`: the integrator's own count (used when
  /// options.passes is 0 and there is no time limit). `now` reads the clock
  /// (default: clockSeconds(options.timeClock)); tests pass their own.
  PassSchedule(const RenderOptions& options, int integratorPasses, std::function<double()> now = {});
  /// Whether to render pass `pass` (asked for 0, 1, 2, ... in order, after the
  /// previous pass finished). Without a time limit: pass < the count. With
  /// one: pass 0 always; a later pass when the cap allows it and the time
  /// spent plus the last pass's time stays within the limit.
  bool startPass(int pass);
  /// The passes the render is expected to make (for the progress bar): the
  /// count, or under a time limit the estimate from the passes so far.
  int expectedPasses() const;
  /// Did the time limit (not the count) end the passes? Valid after startPass returned false.
  bool limitReached() const { return limitReached_; }
  bool timeLimited() const { return limit_ > 0.0; }
  /// Seconds spent since the schedule was made, on its clock.
  double spent() const { return now_() - start_; }

 private:
  std::function<double()> now_;
  double limit_;
  int cap_;  // the most passes (0: no cap; only with a time limit)
  double start_, passStart_, lastPass_ = 0.0;
  int done_ = 0;
  bool limitReached_ = false;
};

}  // namespace femto
