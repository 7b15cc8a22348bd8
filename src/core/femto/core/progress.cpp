#include <femto/core/progress.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace femto {
namespace {

using Clock = std::chrono::steady_clock;
// Redrawing more often than this only costs time (and flickers).
constexpr auto RedrawInterval = std::chrono::milliseconds(100);
constexpr int BarWidth = 30;

std::string formatDuration(double seconds) {
  long s = long(seconds + 0.5);
  char buffer[32];
  if (s >= 3600)
    std::snprintf(buffer, sizeof buffer, "%ldh%02ldm%02lds", s / 3600, (s / 60) % 60, s % 60);
  else if (s >= 60)
    std::snprintf(buffer, sizeof buffer, "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(buffer, sizeof buffer, "%lds", s);
  return buffer;
}

}  // namespace

ProgressReporter::ProgressReporter(std::string label, uint64_t total, bool enabled, ProgressCallback callback)
    : label_(std::move(label)),
      total_(total),
      enabled_(enabled && isatty(STDERR_FILENO)),
      callback_(std::move(callback)),
      start_(Clock::now()),
      lastDraw_(start_ - RedrawInterval) {}

ProgressReporter::~ProgressReporter() { finish(); }

double ProgressReporter::elapsedSeconds() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void ProgressReporter::update(uint64_t delta) {
  uint64_t done = done_.fetch_add(delta) + delta;
  if (!enabled_ && !callback_) return;
  // try_lock: a worker never waits for another one that is drawing.
  std::unique_lock<std::mutex> lock(drawMutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_) return;
  auto now = Clock::now();
  if (now - lastDraw_ < RedrawInterval) return;
  lastDraw_ = now;
  ProgressState current = state(done, false);
  if (enabled_) draw(current);
  if (callback_) callback_(current);
}

void ProgressReporter::finish() {
  std::lock_guard<std::mutex> lock(drawMutex_);
  if (finished_) return;
  finished_ = true;
  ProgressState last = state(done_.load(), true);
  if (enabled_) draw(last);
  if (callback_) callback_(last);
}

ProgressState ProgressReporter::state(uint64_t done, bool final) const {
  ProgressState s;
  s.label = label_;
  const uint64_t total = total_.load();
  s.fraction = total ? std::min(1.0, double(done) / double(total)) : 1.0;
  s.elapsedSeconds = elapsedSeconds();
  // Linear extrapolation of the time per unit of work done so far.
  if (s.fraction > 0 && !final) s.etaSeconds = s.elapsedSeconds * (1 - s.fraction) / s.fraction;
  s.finished = final;
  return s;
}

void ProgressReporter::draw(const ProgressState& s) {
  int filled = int(s.fraction * BarWidth + 0.5);
  std::string bar(size_t(filled), '#');
  bar.append(size_t(BarWidth - filled), ' ');
  std::string eta = s.etaSeconds >= 0 ? ", ETA " + formatDuration(s.etaSeconds) : "";
  // \r and clear-to-end-of-line: the bar overwrites itself on one line.
  std::fprintf(stderr, "\r%s [%s] %5.1f%% (%s%s)\033[K%s", s.label.c_str(), bar.c_str(), s.fraction * 100.0,
               formatDuration(s.elapsedSeconds).c_str(), eta.c_str(), s.finished ? "\n" : "");
  std::fflush(stderr);
}

}  // namespace femto
