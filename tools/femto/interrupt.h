#pragma once
// Signals during a render. The first Ctrl-C (SIGINT) asks the render loop to
// stop: it finishes the tiles in flight and writes a valid partial image (exit
// code 130). A second Ctrl-C, SIGTERM or SIGHUP ends the process at once: the
// temporary files of outputs not yet complete are removed (temp_files.h) and
// the process dies by that signal, so a parent sees it was killed (the shell
// reports 128 + the signal number; Python's returncode is minus it).
#include <atomic>

namespace femto::cli {

class InterruptGuard {
 public:
  /// Installs the handlers; the previous ones are restored on destruction.
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Set by the first Ctrl-C; hand to RenderOptions::cancel.
  const std::atomic<bool>& cancelFlag() const;
  bool interrupted() const { return cancelFlag().load(); }
};

}  // namespace femto::cli
