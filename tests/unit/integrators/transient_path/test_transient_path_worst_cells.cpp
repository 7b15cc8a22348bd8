// A variance regression test on a small fog scene with a point light inside
// it (the hard case of the peer's fog Cornell box, issue 15): how much of the
// error the 1 % worst cells of a transient image hold. With finite variance
// and enough samples, each cell's error is close to normal with that cell's
// own variance, and the worst 1 % of cells hold the share such normal errors
// give (about 8.5 % for cells of equal variance; more when cells differ).
// Fireflies (samples of infinite-variance estimators, such as next-event
// estimates from free-flight vertices near a point light) put one cell's
// error far above its variance, and its share near 1.
//
// The bound is derived from the render itself. Errors are relative, as
// relMSE weighs them: (B - C)^2 / (m^2 + 0.01 mean(m)^2) for two independent
// runs B and C, with m from three further runs (A). Each cell's variance v_i
// is the median of the A runs' estimates (one firefly in one run does not
// raise it), and the share that normal errors of variance 2 v_i give is
// simulated. The test asks that the observed share stay below the largest of
// 400 simulated shares plus 0.1 (the variance estimates' own noise: 300
// samples per cell). Measured: 0.21 against a bound of 0.39 with equiangular
// sampling, 0.47 against 0.37 with free flights alone (second test: the test
// can fail). Single scattering (max_depth 2) keeps it small; the light sits
// inside the footprint of one pixel, so camera rays pass it at every distance.
// Double scattering (max_depth 3), with the light beside the view, tests the
// light-directed vertices (transient_path's light_directions).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include <femto/math/pcg32.h>

#include "media_test_util.h"
#include "plugin_util.h"
#include "transient_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int Pixels = 8, Bins = 16, SamplesPerPixel = 300;

/// The strategies a test renders with, its depth (2: single scattering) and
/// its fog and light.
struct Strategies {
  bool equiangular = true;
  bool lightDirections = true;
  bool timeGating = true;
  int maxDepth = 2;
  float sigmaT = 0.8f, albedo = 0.75f;
  Point3f light{0.05f, 0.02f, 1.0f};
};

std::shared_ptr<Scene> fogWithLight(const Strategies& strategies) {
  const Point3f& light = strategies.light;
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value=")", strategies.maxDepth, R"("/>
    <boolean name="equiangular" value=")", strategies.equiangular ? "true" : "false", R"("/>
    <boolean name="light_directions" value=")", strategies.lightDirections ? "true" : "false", R"("/>
    <boolean name="time_gating" value=")", strategies.timeGating ? "true" : "false", R"("/></integrator>
  <medium id="m" type="homogeneous"><float name="sigma_t" value=")", strategies.sigmaT, R"("/>
    <float name="albedo" value=")", strategies.albedo, R"("/></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x=")",
                             light.x, R"(" y=")", light.y, R"(" z=")", light.z, R"("/>
    <float name="intensity" value="2"/></emitter>
</scene>)"));
}

/// Per-cell (pixel, bin) means and per-sample variances of one run: camera
/// rays from the origin through an 8x8 grid of pixels 0.05 wide on the plane
/// z = 1, jittered within each pixel; bins of 0.25 OPL from 1.
struct CellRun {
  std::vector<double> mean, variance;
};

CellRun render(const Scene& scene, uint64_t seed) {
  const TimeGrid grid{1.0, 0.25, Bins};
  CellRun run;
  run.mean.assign(Pixels * Pixels * Bins, 0.0);
  run.variance.assign(run.mean.size(), 0.0);
  auto sampler = seededSampler(seed);
  PCG32 rng(seed, 3);
  std::vector<double> path(Bins), sum(Bins), sumSq(Bins);
  for (int py = 0; py < Pixels; ++py)
    for (int px = 0; px < Pixels; ++px) {
      std::fill(sum.begin(), sum.end(), 0.0);
      std::fill(sumSq.begin(), sumSq.end(), 0.0);
      for (int i = 0; i < SamplesPerPixel; ++i) {
        Vec3f target((px - Pixels / 2 + rng.nextFloat()) * 0.05f, (py - Pixels / 2 + rng.nextFloat()) * 0.05f, 1.0f);
        CollectingRecorder recorder(grid);
        transientIntegrator(scene).sample(scene, Ray(Point3f(0.0f), normalize(target)), *sampler, recorder);
        std::fill(path.begin(), path.end(), 0.0);
        for (const auto& [opl, value] : recorder.hits)
          if (int bin = grid.binOf(opl); bin >= 0) path[bin] += value.g;
        for (int b = 0; b < Bins; ++b) sum[b] += path[b], sumSq[b] += path[b] * path[b];
      }
      for (int b = 0; b < Bins; ++b) {
        size_t cell = size_t((py * Pixels + px) * Bins + b);
        double m = sum[b] / SamplesPerPixel;
        run.mean[cell] = m;
        run.variance[cell] = std::max(0.0, sumSq[b] / SamplesPerPixel - m * m) / SamplesPerPixel;
      }
    }
  return run;
}

/// Share of the total held by the largest 1 % of `squares`.
double worstShare(std::vector<double> squares) {
  size_t worst = std::max<size_t>(1, squares.size() / 100);
  std::partial_sort(squares.begin(), squares.begin() + worst, squares.end(), std::greater<>());
  double total = std::accumulate(squares.begin(), squares.end(), 0.0);
  return total > 0.0 ? std::accumulate(squares.begin(), squares.begin() + worst, 0.0) / total : 0.0;
}

/// The observed share and the bound normal errors of run A's variances give.
std::pair<double, double> shareAndBound(const Scene& scene) {
  CellRun b = render(scene, 1), c = render(scene, 2);
  std::vector<CellRun> a = {render(scene, 3), render(scene, 4), render(scene, 5)};
  // Relative errors, as relMSE weighs them: normalised by the cell's value
  // (from runs independent of B and C) plus 1 % of the mean cell's square.
  std::vector<double> squares(b.mean.size()), variance(b.mean.size()), scale(b.mean.size());
  double meanCell = 0.0;
  for (size_t i = 0; i < scale.size(); ++i)
    meanCell += (a[0].mean[i] + a[1].mean[i] + a[2].mean[i]) / 3.0 / double(scale.size());
  for (size_t i = 0; i < squares.size(); ++i) {
    double m = (a[0].mean[i] + a[1].mean[i] + a[2].mean[i]) / 3.0;
    scale[i] = 1.0 / (m * m + 0.01 * meanCell * meanCell);
    squares[i] = (b.mean[i] - c.mean[i]) * (b.mean[i] - c.mean[i]) * scale[i];
    // The median of three runs' estimates: a firefly in one run's cell would
    // otherwise raise that cell's variance, and the bound, with it.
    double v[3] = {a[0].variance[i], a[1].variance[i], a[2].variance[i]};
    std::sort(v, v + 3);
    variance[i] = v[1];
  }
  PCG32 rng(99, 5);
  double largest = 0.0;
  std::vector<double> simulated(squares.size());
  for (int k = 0; k < 400; ++k) {
    for (size_t i = 0; i < simulated.size(); ++i) {
      // Box-Muller: one standard normal per cell.
      double u1 = 1.0 - rng.nextFloat(), u2 = rng.nextFloat();
      double z = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * Pi * u2);
      simulated[i] = 2.0 * variance[i] * z * z * scale[i];
    }
    largest = std::max(largest, worstShare(simulated));
  }
  return {worstShare(squares), largest + 0.1};
}

/// A light beside the view: the pixels span x in [-0.2, 0.2] at z = 1, so
/// camera rays pass it at 0.25 or more and its single scattering is smooth;
/// only rays leaving scattering vertices pass it at every distance.
const Point3f LightBesideTheView(0.45f, 0.02f, 1.0f);
}  // namespace

TEST(TransientPathWorstCells, WorstOnePercentOfCellsHoldNoMoreThanNormalErrorsWould) {
  auto [share, bound] = shareAndBound(*fogWithLight({}));
  EXPECT_LT(share, bound) << "the worst 1 % of cells hold " << share << " of the squared error";
}

TEST(TransientPathWorstCells, FreeFlightsAloneExceedTheBound) {
  // The test's power: free-flight vertices alone (infinite variance near the
  // light) put the error in a few cells. Ungated: time gating keeps free
  // flights within reach of the window (0.22 against 0.34 gated).
  auto [share, bound] =
      shareAndBound(*fogWithLight({.equiangular = false, .lightDirections = false, .timeGating = false}));
  EXPECT_GT(share, bound) << "the worst 1 % of cells hold " << share << " of the squared error";
}

TEST(TransientPathWorstCells, DoubleScatteringWithLightDirectedVerticesStaysWithinTheBound) {
  // Rays leaving the first scattering vertex pass the light at every distance
  // h; without light-directed vertices their equiangular estimates (~ 1/h)
  // have unbounded variance (issue 15's fireflies). Measured: 0.11 against a
  // bound of 0.27; 0.83 against 0.31 without them (next test).
  auto [share, bound] = shareAndBound(*fogWithLight({.maxDepth = 3, .light = LightBesideTheView}));
  EXPECT_LT(share, bound) << "the worst 1 % of cells hold " << share << " of the squared error";
}

TEST(TransientPathWorstCells, DoubleScatteringWithoutLightDirectedVerticesExceedsTheBound) {
  auto [share, bound] = shareAndBound(*fogWithLight({.lightDirections = false, .maxDepth = 3, .light = LightBesideTheView}));
  EXPECT_GT(share, bound) << "the worst 1 % of cells hold " << share << " of the squared error";
}
