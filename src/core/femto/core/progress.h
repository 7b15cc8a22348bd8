#pragma once
// Progress bar with ETA, drawn on stderr only when it is a terminal; the same
// numbers can also go to a callback (an embedding program's own progress
// display, e.g. the Python module's).
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

namespace femto {

/// What the progress bar shows.
struct ProgressState {
  std::string label;      // "Rendering"
  double fraction = 0.0;  // of the work done, 0..1
  double elapsedSeconds = 0.0;
  double etaSeconds = -1.0;  // estimated seconds left; negative while unknown (nothing done yet) and when finished
  bool finished = false;     // the last report of this bar
};
/// Called as the bar would be redrawn (at most every 100 ms, from whichever
/// worker thread updates it, never by two threads at once) and once at the end.
using ProgressCallback = std::function<void(const ProgressState&)>;

class ProgressReporter {
 public:
  /// `callback` (may be empty) is called whether or not stderr is a terminal
  /// and whether or not the bar is `enabled`.
  ProgressReporter(std::string label, uint64_t total, bool enabled = true, ProgressCallback callback = {});
  ~ProgressReporter();
  void update(uint64_t delta);  // thread-safe
  /// A new estimate of the whole job (a time-limited render learns its pass
  /// count as it goes); call between updates, not during them.
  void setTotal(uint64_t total) { total_ = total; }
  void finish();
  double elapsedSeconds() const;

 private:
  ProgressState state(uint64_t done, bool final) const;
  void draw(const ProgressState& state);
  std::string label_;
  std::atomic<uint64_t> total_;
  bool enabled_;
  ProgressCallback callback_;
  std::atomic<uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::mutex drawMutex_;
  std::chrono::steady_clock::time_point lastDraw_;
  bool finished_ = false;
};

}  // namespace femto
