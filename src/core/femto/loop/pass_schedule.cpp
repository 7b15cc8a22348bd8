// The pass count of a progressive render, fixed or from a time budget (pass_schedule.h).
#include <femto/loop/pass_schedule.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include <femto/base/error.h>

namespace femto {

double clockSeconds(RenderClock clock) {
  if (clock == RenderClock::Cpu) {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

const char* clockName(RenderClock clock) { return clock == RenderClock::Cpu ? "cpu" : "wall"; }

PassSchedule::PassSchedule(const RenderOptions& options, int integratorPasses, std::function<double()> now)
    : now_(now ? std::move(now) : std::function<double()>([clock = options.timeClock] { return clockSeconds(clock); })),
      limit_(options.timeLimit),
      cap_(options.passes > 0 ? options.passes : (options.timeLimit > 0.0 ? 0 : std::max(integratorPasses, 1))) {
  if (!(limit_ >= 0.0) || !std::isfinite(limit_))
    throw Error(str("the time limit must be a number of seconds > 0, got ", limit_));
  start_ = passStart_ = now_();
}

bool PassSchedule::startPass(int pass) {
  const double t = now_();
  if (pass > 0) {
    lastPass_ = t - passStart_;
    done_ = pass;
  }
  passStart_ = t;
  if (cap_ > 0 && pass >= cap_) return false;
  if (limit_ > 0.0 && pass > 0 && (t - start_) + lastPass_ > limit_) {
    limitReached_ = true;
    return false;
  }
  return true;
}

int PassSchedule::expectedPasses() const {
  if (limit_ <= 0.0) return cap_;
  if (done_ == 0 || !(lastPass_ > 0.0)) return cap_ > 0 ? std::min(cap_, 2) : 2;  // nothing measured yet
  const double left = std::max(limit_ - spent(), 0.0);
  const int more = int(std::min(left / lastPass_, 1e6));
  const int estimate = done_ + std::max(more, 1);  // the pass about to start and those the time left holds
  return cap_ > 0 ? std::min(cap_, estimate) : estimate;
}

}  // namespace femto
