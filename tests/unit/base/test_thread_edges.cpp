// ForkJoinEdges states oneTBB's hand-offs for ThreadSanitizer (Debian's libtbb
// is not instrumented). Under `make sanitize-thread` the first test fails with
// a data race report when an edge is missing (checked by removing the
// task() wrapper or the join()); in other builds the tests check that the
// wrappers pass arguments and results through unchanged.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <vector>

#include <femto/base/thread_edges.h>

namespace femto {
namespace {

TEST(ThreadEdges, TasksSeeTheSpawnersWritesAndTheJoinSeesTheTasks) {
  tbb::task_arena arena(2);
  // Start the workers first: creating a thread is an edge TSan sees by itself,
  // which would hide a missing fork edge in the first region.
  arena.execute([] { tbb::parallel_for(0, 1000, [](int) {}); });
  const int n = 256;
  std::vector<int> input(n), output(n);
  for (int round = 0; round < 8; ++round) {
    for (int i = 0; i < n; ++i) input[size_t(i)] = i + round;  // plain writes before the fork
    auto body = [&](int i) {
      int v = input[size_t(i)];
      for (int k = 0; k < 200; ++k) v = (v * 7 + k) % 1000003;  // enough work that workers steal
      output[size_t(i)] = v;
    };
    ForkJoinEdges edges;
    arena.execute([&] { tbb::parallel_for(0, n, edges.task(body)); });
    edges.join();
    for (int i = 0; i < n; ++i) {  // plain reads after the join
      int v = i + round;
      for (int k = 0; k < 200; ++k) v = (v * 7 + k) % 1000003;
      ASSERT_EQ(output[size_t(i)], v) << "round " << round << ", item " << i;
    }
  }
}

TEST(ThreadEdges, ExecuteInArenaReturnsTheBodysResult) {
  tbb::task_arena arena(2);
  int x = 41;
  EXPECT_EQ(executeInArena(arena, [&] { return x + 1; }), 42);
  executeInArena(arena, [&] { x = 7; });
  EXPECT_EQ(x, 7);
}

}  // namespace
}  // namespace femto
