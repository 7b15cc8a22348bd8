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

/// The edges of one fork-join region. Make it on the spawning thread after
/// everything the tasks read is written, just before the region (its
/// constructor is the fork); hand TBB the task bodies through task(); call
/// join() once the region has returned. Each body then sees what the spawner
/// wrote before the fork, and the spawner sees what every body wrote.
class ForkJoinEdges {
 public:
  ForkJoinEdges() { releaseTo(&fork_); }
  ForkJoinEdges(const ForkJoinEdges&) = delete;
  ForkJoinEdges& operator=(const ForkJoinEdges&) = delete;

  /// `body` as a task of this region (see TbbTask); `body` must outlive the region.
  template <typename Body>
  auto task(Body& body) const;

  /// A task body starts: after the fork.
  void enter() const { acquireFrom(&fork_); }
  /// A task body ends: before the join.
  void leave() const { releaseTo(&join_); }
  /// Call on the spawning thread after the region has returned.
  void join() const { acquireFrom(&join_); }

 private:
  char fork_ = 0, join_ = 0;
};

/// A task body of one fork-join region as TBB copies and calls it: a pointer
/// to the region's edges and one to the body, which was made before the
/// fork. TBB copies this object on the spawning thread after the fork, in
/// its own code, and hands the copy over inside libtbb; reading the two
/// pointers is the one access TSan cannot order, and
/// tools/sanitize/tsan-tbb.supp names this class for it (race_top: only
/// the reads in this frame, not those of the body it calls).
template <typename Body>
class TbbTask {
 public:
  TbbTask(const ForkJoinEdges& edges, Body& body) : edges_(&edges), body_(&body) {}

  template <typename... Args>
  decltype(auto) operator()(Args&&... args) const {
    const ForkJoinEdges& edges = *edges_;
    Body& body = *body_;
    edges.enter();
    struct Leave {
      const ForkJoinEdges& edges;
      ~Leave() { edges.leave(); }
    } leave{edges};
    return body(std::forward<Args>(args)...);
  }

 private:
  const ForkJoinEdges* edges_;
  Body* body_;
};

template <typename Body>
auto ForkJoinEdges::task(Body& body) const {
  return TbbTask<Body>(*this, body);
}

/// Runs `body` through `arena` (a tbb::task_arena, or anything with
/// execute()), which may hand it to another thread, with the fork and join
/// edges stated; returns what `body` returns. `body` is made before the
/// fork (it is an argument), so it may be a temporary.
template <typename Arena, typename Body>
decltype(auto) executeInArena(Arena& arena, Body&& body) {
  ForkJoinEdges edges;
  struct Join {
    const ForkJoinEdges& edges;
    ~Join() { edges.join(); }
  } join{edges};
  return arena.execute(edges.task(body));
}

}  // namespace femto
