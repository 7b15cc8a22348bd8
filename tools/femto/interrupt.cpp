#include "interrupt.h"

#include <csignal>
#include <cstring>
#include <unistd.h>

namespace femto::cli {
namespace {

// A signal handler may only touch lock-free atomics.
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> gCancel{false};
struct sigaction gPrevious, gPreviousUsr1;

void writeStderr(const char* message) {
  // write(2) is async-signal-safe; iostreams and printf are not.
  ssize_t ignored = write(STDERR_FILENO, message, std::strlen(message));
  (void)ignored;
}

extern "C" void onInterrupt(int) {
  if (gCancel.exchange(true)) {
    writeStderr("\ninterrupted again: exiting without writing an image\n");
    _exit(130);  // 128 + SIGINT, as shells report it
  }
  writeStderr("\ninterrupted: finishing and writing the partial image (Ctrl-C again to quit at once)\n");
}

}  // namespace

InterruptGuard::InterruptGuard() {
  gCancel = false;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &gPrevious);
  sigaction(SIGUSR1, &action, &gPreviousUsr1);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &gPrevious, nullptr);
  sigaction(SIGUSR1, &gPreviousUsr1, nullptr);
}

const std::atomic<bool>& InterruptGuard::cancelFlag() const { return gCancel; }

}  // namespace femto::cli
