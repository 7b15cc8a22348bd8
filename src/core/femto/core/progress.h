#pragma once
// Progress bar with ETA, drawn on stderr only when it is a terminal.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace femto {

class ProgressReporter {
 public:
  ProgressReporter(std::string label, uint64_t total, bool enabled = true);
  ~ProgressReporter();
  void update(uint64_t delta);  // thread-safe
  void finish();
  double elapsedSeconds() const;

 private:
  void draw(uint64_t done, bool final);
  std::string label_;
  uint64_t total_;
  bool enabled_;
  std::atomic<uint64_t> done_{0};
  std::chrono::steady_clock::time_point start_;
  std::mutex drawMutex_;
  std::chrono::steady_clock::time_point lastDraw_;
  bool finished_ = false;
};

}  // namespace femto
