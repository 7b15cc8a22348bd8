#pragma once
// Per-bin and total estimates of what a transient integrator records inside
// a time window, over camera rays from a generator: the harness of tests that
// compare two estimators of the same window (time gating, light-directed
// vertices) or one against a closed form.
#include <algorithm>
#include <vector>

#include <femto/math/pcg32.h>
#include <femto/render/scene.h>

#include "media_test_util.h"
#include "transient_test_util.h"

namespace femto::test {

/// Per-sample totals of what `scene` records inside `grid`'s window along
/// rays from `rays` (one Mean per bin, and the window's total), and of what
/// it records before the window (the film's _before).
struct WindowEstimate {
  std::vector<Mean> bins;
  Mean total;
  Mean before;
};

template <typename RayFn>
WindowEstimate estimateWindow(const Scene& scene, const TimeGrid& grid, int n, uint64_t seed, RayFn&& rays) {
  WindowEstimate e;
  e.bins.resize(grid.bins);
  auto sampler = seededSampler(seed);
  PCG32 rng(seed, 1);
  std::vector<double> path(grid.bins);
  for (int i = 0; i < n; ++i) {
    CollectingRecorder recorder(grid);
    transientIntegrator(scene).sample(scene, rays(rng), *sampler, recorder);
    std::fill(path.begin(), path.end(), 0.0);
    double sum = 0.0, before = 0.0;
    for (const auto& [opl, value] : recorder.hits) {
      if (opl < grid.start) before += value.g;
      int bin = grid.binOf(opl);
      if (bin < 0) continue;
      path[bin] += value.g;
      sum += value.g;
    }
    for (int b = 0; b < grid.bins; ++b) e.bins[b].add(path[b]);
    e.total.add(sum);
    e.before.add(before);
  }
  return e;
}

}  // namespace femto::test
