#pragma once
// Happens-before edges that ThreadSanitizer cannot see by itself.
//
// Debian's libtbb is not built with -fsanitize=thread, so the synchronisation
// inside it (a task spawned on one thread and run on another, a pipeline item
// passed from one stage to the next, the wait for a parallel region to end)
// is invisible to TSan, which then reports every hand-off as a race. These
// calls state, through TSan's annotation interface, the edges oneTBB
// guarantees; in any other build they compile to nothing. They are placed
// where femto hands work to TBB (the render loop's pipeline, the photon
// tracer's parallel_for, task arenas, frame writing), so a race TSan reports
// is one between femto's own tasks.
#if defined(__SANITIZE_THREAD__)
#define FEMTO_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define FEMTO_THREAD_SANITIZER 1
#endif
#endif

#ifdef FEMTO_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>
#endif

#include <utility>

namespace femto {

/// What this thread wrote so far happens before whatever a thread does after
/// acquireFrom(address) with the same address (a release on a sync object).
inline void releaseTo([[maybe_unused]] const void* address) {
#ifdef FEMTO_THREAD_SANITIZER
  __tsan_release(const_cast<void*>(address));
#endif
}

/// Everything released to `address` so far happens before what this thread does next.
inline void acquireFrom([[maybe_unused]] const void* address) {
#ifdef FEMTO_THREAD_SANITIZER
  __tsan_acquire(const_cast<void*>(address));
#endif
}

/// The edges of one fork-join region. Make it on the spawning thread just
/// before the region (its constructor is the fork), run every task body
/// through task() or inside a TaskScope, and call join() once the region
/// has returned: each body then sees what the spawner wrote before the fork,
/// and the spawner sees what every body wrote.
class ForkJoinEdges {
 public:
  ForkJoinEdges() { releaseTo(&fork_); }
  ForkJoinEdges(const ForkJoinEdges&) = delete;
  ForkJoinEdges& operator=(const ForkJoinEdges&) = delete;

  /// Marks one task body: entered after the fork, left before the join.
  class TaskScope {
   public:
    explicit TaskScope(const ForkJoinEdges& edges) : edges_(edges) { acquireFrom(&edges_.fork_); }
    ~TaskScope() { releaseTo(&edges_.join_); }
    TaskScope(const TaskScope&) = delete;
    TaskScope& operator=(const TaskScope&) = delete;

   private:
    const ForkJoinEdges& edges_;
  };

  /// `body` wrapped as a task of this region (called with the same arguments).
  template <typename Body>
  auto task(Body& body) const {
    return [this, &body](auto&&... args) -> decltype(auto) {
      TaskScope scope(*this);
      return body(std::forward<decltype(args)>(args)...);
    };
  }

  /// Call on the spawning thread after the region has returned.
  void join() const { acquireFrom(&join_); }

 private:
  char fork_ = 0, join_ = 0;
};

/// Runs `body` through `arena` (a tbb::task_arena, or anything with
/// execute()), which may hand it to another thread, with the fork and join
/// edges stated; returns what `body` returns.
template <typename Arena, typename Body>
decltype(auto) executeInArena(Arena& arena, Body&& body) {
  ForkJoinEdges edges;
  auto task = edges.task(body);
  struct Join {
    const ForkJoinEdges& edges;
    ~Join() { edges.join(); }
  } join{edges};
  return arena.execute(task);
}

}  // namespace femto
