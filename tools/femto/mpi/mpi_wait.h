#pragma once
// Waiting for MPI without spinning a core: Open MPI's blocking calls poll
// at full speed, which on a node shared with the render threads (or a rank
// waiting while rank 0 writes the outputs) takes a core from the work.
#include <mpi.h>

#include <chrono>
#include <thread>

namespace femto::cli {

/// How long an idle main thread sleeps before polling MPI again (a finished
/// local tile wakes it at once): short next to a tile's render time (tens of
/// milliseconds and more; the ranks keep 2 x threads + 2 tiles assigned, so a
/// late answer costs nothing), long enough that waking costs little.
inline constexpr std::chrono::microseconds PollInterval(1000);

/// Completes `request` (a non-blocking operation), sleeping between tests.
inline void waitSleeping(MPI_Request& request) {
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    std::this_thread::sleep_for(PollInterval);
  }
}

}  // namespace femto::cli
