#pragma once
// Agreement of two transient renderers on the same small scene (the
// transient_beams tests compare against transient_path): renders to scratch
// files, per-time-bin image sums over independent runs, and a per-bin check
// within the runs' spread plus a stated kernel-bias allowance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/render/scene.h>

#include "media_test_util.h"
#include "render_test_util.h"
#include "transient_film_test_util.h"

namespace femto::test {

struct Rendered {
  std::vector<float> volume;  // (h, w, bins, 3)
  Bitmap steady;
  int h = 0, w = 0, bins = 0;
};

/// Render `scene` to `out` (steady image) and its `.npy` volume (transient
/// films). Fails the test when the render stops early, the film rejected
/// samples, or any stored value is NaN or infinite.
inline Rendered render(const std::shared_ptr<Scene>& scene, const std::filesystem::path& out, uint64_t seed,
                       int threads = 0) {
  RenderOptions options;
  options.output = out;
  options.seed = seed;
  options.progress = false;
  options.threads = threads;
  RenderStats stats = scene->integrator().render(*scene, options);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  Rendered r;
  r.steady = readImage(out);
  std::filesystem::path npy = std::filesystem::path(out).replace_extension(".npy");
  if (std::filesystem::exists(npy)) r.volume = readVolume(npy, r.h, r.w, r.bins);
  size_t nonFinite = 0;
  for (float v : r.volume) nonFinite += !std::isfinite(v);
  for (int y = 0; y < r.steady.height; ++y)
    for (int x = 0; x < r.steady.width; ++x)
      for (int c = 0; c < 3; ++c) nonFinite += !std::isfinite(r.steady.pixel(x, y)[c]);
  EXPECT_EQ(nonFinite, 0u) << "NaN or Inf reached the film of " << out;
  return r;
}

/// A positive integer from the environment, or `fallback`: the benchmark
/// scripts under tools/bench run these tests longer through it.
inline int environmentCount(const char* name, int fallback) {
  const char* n = std::getenv(name);
  return n ? std::max(1, std::atoi(n)) : fallback;
}

/// Per run (seeds seed0, seed0 + 1, ...), per time bin and one more entry
/// for the steady image: the image sum of the channel average.
inline std::vector<std::vector<double>> imageSumsPerRun(const std::shared_ptr<Scene>& scene, const std::string& name,
                                                        int runs, uint64_t seed0 = 100) {
  auto dir = scratchDir(name);
  std::vector<std::vector<double>> perRun;
  for (int run = 0; run < runs; ++run) {
    Rendered r = render(scene, dir / "out.exr", seed0 + uint64_t(run));
    std::vector<double>& perBin = perRun.emplace_back(size_t(r.bins) + 1, 0.0);
    for (size_t i = 0; i < r.volume.size(); ++i) perBin[(i / 3) % size_t(r.bins)] += r.volume[i] / 3.0;
    for (int y = 0; y < r.steady.height; ++y)
      for (int x = 0; x < r.steady.width; ++x)
        for (int c = 0; c < 3; ++c) perBin.back() += r.steady.pixel(x, y)[c] / 3.0;
  }
  std::filesystem::remove_all(dir);
  return perRun;
}

/// The same sums as means over the runs.
inline std::vector<Mean> imageSums(const std::shared_ptr<Scene>& scene, const std::string& name, int runs,
                                   uint64_t seed0 = 100) {
  std::vector<Mean> sums;
  for (const std::vector<double>& perBin : imageSumsPerRun(scene, name, runs, seed0)) {
    sums.resize(perBin.size());
    for (size_t b = 0; b < perBin.size(); ++b) sums[b].add(perBin[b]);
  }
  return sums;
}

/// Two sets of independent runs estimate the same quantities: each pair of
/// means within 5 standard errors of their difference (the runs' spread),
/// plus `bias` times the value for what a density estimate's kernel may
/// shift (0 between unbiased estimators).
inline void expectAgree(const std::vector<Mean>& a, const std::vector<Mean>& b, const char* what, double bias = 0.0) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) {
    double se = std::sqrt(a[k].standardError() * a[k].standardError() + b[k].standardError() * b[k].standardError());
    std::printf("%s %s: %.5g +- %.2g vs %.5g +- %.2g\n", what,
                k + 1 == a.size() ? "steady" : str("bin ", k).c_str(), a[k].mean(), a[k].standardError(), b[k].mean(),
                b[k].standardError());
    EXPECT_NEAR(a[k].mean(), b[k].mean(), 5.0 * se + bias * std::abs(b[k].mean()) + 1e-6)
        << what << (k + 1 == a.size() ? " steady" : " bin ") << k;
  }
}

/// transient_beams' kernels are consistent, not unbiased: near a medium's
/// boundary part of a beam kernel falls outside it, so the estimate is low
/// there (the surface kernel divides by its disc's area on the surface,
/// surface_coverage.h, and keeps the ring's quadrature error, ~3 % of what an
/// edge would lose). With the default radii (derived from pass 0's beams and
/// photons, the beams' at most 1 % of the scene's diagonal) the band within a
/// radius of a boundary is a few percent of what the camera sees and loses at
/// most half of its light there: allow 2 % of the value on top of the noise.
constexpr double KernelBias = 0.02;

}  // namespace femto::test
