#pragma once
// Ctrl-C handling for renders: the first SIGINT asks the render loop to stop
// (it still writes a valid partial image); a second one exits at once.
#include <atomic>

namespace femto::cli {

class InterruptGuard {
 public:
  /// Installs the SIGINT handler; the previous handler is restored on destruction.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Set by the first Ctrl-C; hand to RenderOptions::cancel.
  const std::atomic<bool>& cancelFlag() const;
  bool interrupted() const { return cancelFlag().load(); }
};

}  // namespace femto::cli
