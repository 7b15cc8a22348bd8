#pragma once
// Ctrl-C handling for renders: the first SIGINT asks the render loop to stop
// (it still writes a valid partial image); a second one exits at once.
// SIGUSR1 asks the same as the first Ctrl-C: Open MPI's mpirun forwards it to
// every rank (`kill -USR1 <mpirun>`), while a Ctrl-C on mpirun ends the
// ranks at once (it cannot forward SIGINT), writing nothing.
#include <atomic>

namespace femto::cli {

class InterruptGuard {
 public:
  /// Installs the SIGINT and SIGUSR1 handlers; the previous ones are restored on destruction.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Set by the first Ctrl-C; hand to RenderOptions::cancel.
  const std::atomic<bool>& cancelFlag() const;
  bool interrupted() const { return cancelFlag().load(); }
};

}  // namespace femto::cli
