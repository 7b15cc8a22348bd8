#include "interrupt.h"

#include <pthread.h>

#include <csignal>
#include <cstring>
#include <unistd.h>

#include <femto/base/temp_files.h>

namespace femto::cli {
namespace {

// A signal handler may only touch lock-free atomics.
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> gCancel{false};
constexpr int HandledSignals[] = {SIGINT, SIGTERM, SIGHUP};
struct sigaction gPrevious[3];

void writeStderr(const char* message) {
  // write(2) is async-signal-safe; iostreams and printf are not.
  ssize_t ignored = write(STDERR_FILENO, message, std::strlen(message));
  (void)ignored;
}

/// Remove what is not complete, then die by `signal` itself (default action).
[[noreturn]] void endBySignal(int signal) {
  removeTempFilesNow();
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  sigemptyset(&fallback.sa_mask);
  sigaction(signal, &fallback, nullptr);
  // The handler runs with its signal blocked: unblock it, or raise() would
  // only leave it pending.
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, signal);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  raise(signal);
  _exit(128 + signal);  // only if the default action returned (it does not for these signals)
}

extern "C" void onSignal(int signal) {
  if (signal == SIGINT && !gCancel.exchange(true)) {
    writeStderr("\ninterrupted: finishing and writing the partial image (Ctrl-C again to quit at once)\n");
    return;
  }
  writeStderr(signal == SIGINT ? "\ninterrupted again: quitting at once; unfinished outputs are removed\n"
                               : "\nterminated: quitting at once; unfinished outputs are removed\n");
  endBySignal(signal);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  gCancel = false;
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  for (int k = 0; k < 3; ++k) sigaction(HandledSignals[k], &action, &gPrevious[k]);
}

InterruptGuard::~InterruptGuard() {
  for (int k = 0; k < 3; ++k) sigaction(HandledSignals[k], &gPrevious[k], nullptr);
}

const std::atomic<bool>& InterruptGuard::cancelFlag() const { return gCancel; }

}  // namespace femto::cli
