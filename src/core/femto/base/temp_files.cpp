#include <femto/base/temp_files.h>

#include <unistd.h>

#include <atomic>
#include <cstring>

namespace femto {
namespace {

// Fixed storage: a signal handler can neither allocate nor lock. A slot is
// Free, being Written by the registering thread, or Live (its path complete).
// The handler unlinks Live slots only, so it never reads a half-copied path.
// Enough slots for the volume plus every frame written in parallel.
constexpr int SlotCount = 256;
constexpr size_t PathBytes = 4096;
enum SlotState : int { Free, Written, Live };
static_assert(std::atomic<int>::is_always_lock_free);

struct Slot {
  std::atomic<int> state{Free};
  char path[PathBytes];
};
Slot gSlots[SlotCount];

}  // namespace

TempFileGuard::TempFileGuard(const std::filesystem::path& path) {
  const std::string& text = path.native();
  if (text.size() >= PathBytes) return;  // untracked; the destructor-based cleanup still applies
  for (int k = 0; k < SlotCount; ++k) {
    int expected = Free;
    if (!gSlots[k].state.compare_exchange_strong(expected, Written)) continue;
    std::memcpy(gSlots[k].path, text.c_str(), text.size() + 1);
    gSlots[k].state.store(Live, std::memory_order_release);
    slot_ = k;
    return;
  }
}

void TempFileGuard::release() {
  if (slot_ < 0) return;
  gSlots[slot_].state.store(Free, std::memory_order_release);
  slot_ = -1;
}

void removeTempFilesNow() noexcept {
  for (Slot& slot : gSlots)
    if (slot.state.load(std::memory_order_acquire) == Live) ::unlink(slot.path);
}

}  // namespace femto
