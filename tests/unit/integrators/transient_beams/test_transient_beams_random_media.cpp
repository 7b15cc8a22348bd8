// Randomised media scenes (media_scene_generator.h, seeded): transient_beams
// at its defaults (derived radius; max_depth 2) against transient_path, an
// independent unbiased estimator, on the same scene: the window sum and four
// coarse bins agree within 5 standard errors of the runs' means plus the
// beams' derived bias bound (boundary loss below BoundaryBiasTarget, a pair's
// time footprint: half a fine bin's mass each side of an edge); where the
// light is not near the view both window sums also agree with the closed
// form of single scattering within that plus its quadrature's error; the two
// bins ending before the earliest possible arrival are exactly empty in both;
// no NaN or Inf reaches the film (render() checks). CI runs seeds 1-3;
// FEMTO_MEDIA_SWEEP=N runs seeds 1..N (tools/bench/random_media_sweep.sh),
// FEMTO_MEDIA_SEED=k seed k alone, FEMTO_MEDIA_RUNS=n n >= 2 runs per
// renderer (default 4; the spread needs two), FEMTO_MEDIA_PASSES=p beams
// passes per run (default 2): how a suspected bias is measured beyond the CI
// runs' noise (tools/bench/random_media_seed.sh); FEMTO_MEDIA_XML=dir also
// writes each seed's two scenes there, for `femto render`.
//
// The tolerance is noise-limited where the camera is inside a medium: every
// camera ray starts at the same point, so a beam passing at distance rho from
// the camera crosses many pixels and adds ~1/rho to the image sum (rho > r);
// the image sum's variance grows as ln(extent / r) / N (beams per pass), not
// 1/(pixels N). On seed 3 (camera and light inside a sphere) one 2-pass run's
// window sum scatters by ~6 % (22x the variance of independent pixels), so 4
// runs resolve ~3 % and 5 sigma is ~13 %: the printed tolerance says it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <transient_beams/radius_rule.h>

#include "media_scene_generator.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::string integratorXml(const char* type, const MediaScene& m, int passes) {
  return str(R"(<integrator type=")", type, R"("><integer name="max_depth" value="2"/>)",
             passes > 0 ? str(R"(<integer name="passes" value=")", passes, R"("/>)") : std::string(),
             R"(<boolean name="observer_time" value=")", m.model.observerTime ? "true" : "false",
             R"("/></integrator>)");
}

/// Per coarse bin (4 fine bins each) and the window: the runs' means.
std::vector<Mean> coarseSums(const std::vector<std::vector<double>>& perRun, int bins, const std::string& what) {
  const int per = 4, coarse = bins / per;
  std::vector<Mean> sums(size_t(coarse) + 1);
  for (const auto& run : perRun) {
    EXPECT_EQ(run[0], 0.0) << what << ": energy in bin 0, before the earliest possible arrival";
    EXPECT_EQ(run[1], 0.0) << what << ": energy in bin 1, before the earliest possible arrival";
    std::vector<double> c(size_t(coarse) + 1, 0.0);
    for (int b = 0; b < bins; ++b) c[size_t(b / per)] += run[size_t(b)], c.back() += run[size_t(b)];
    for (size_t k = 0; k < c.size(); ++k) sums[k].add(c[k]);
  }
  return sums;
}

/// One generated scene: beams against path (runs each), the window and
/// coarse bins, and nothing before the earliest arrival.
void checkSeed(int seed, int runs, int passes) {
  const char* xmlDir = std::getenv("FEMTO_MEDIA_XML");
  MediaScene m = randomMediaScene(uint64_t(seed));
  const std::string what =
      str("seed ", seed, " (", m.model.bounded ? "sphere" : "unbounded", ", light ", m.lightInside() ? "in" : "out",
          ", camera ", m.cameraInside() ? "in" : "out", ", sigma_t ", m.model.sigmaT, ", eta ", m.model.eta,
          ", observer time ", m.model.observerTime ? "on" : "off", ")");
  std::printf("%s\n", what.c_str());
  MediaScene path = m;
  path.spp = 64;
  const std::string beamsXml = m.xml(integratorXml("transient_beams", m, passes));
  const std::string pathXml = path.xml(integratorXml("transient_path", m, 0));
  if (xmlDir) {
    std::ofstream(std::filesystem::path(xmlDir) / str("seed", seed, "-beams.xml")) << beamsXml;
    std::ofstream(std::filesystem::path(xmlDir) / str("seed", seed, "-path.xml")) << pathXml;
  }
  auto beamsScene = loadSceneStrict(beamsXml);
  auto pathScene = loadSceneStrict(pathXml);
  const auto beamRuns = imageSumsPerRun(beamsScene, str("random-media-beams-", seed), runs);
  const auto pathRuns = imageSumsPerRun(pathScene, str("random-media-path-", seed), runs);
  const std::vector<Mean> b = coarseSums(beamRuns, m.grid.bins, what + " beams");
  const std::vector<Mean> p = coarseSums(pathRuns, m.grid.bins, what + " path");
  // Fine-bin means of path for the time-footprint slack.
  std::vector<double> fine(size_t(m.grid.bins), 0.0);
  for (const auto& run : pathRuns)
    for (int k = 0; k < m.grid.bins; ++k) fine[size_t(k)] += run[size_t(k)] / runs;
  const double boundary = m.model.bounded ? beams::BoundaryBiasTarget : 0.0;
  // The closed form's window sum too, at n x n and n/2 x n/2 sub-rays per
  // pixel: the midpoint rule's error across silhouettes falls as 1/n, so
  // their difference bounds the finer one's (seed 6: 2.6103 at 4, 2.5623 at
  // 16, 2.5635 at 64; path at 8 x 16384 spp 2.5609 +- 0.0017). With the
  // light near the view its pixel's 1/h is only approximated: not checked.
  const int steps = environmentCount("FEMTO_MEDIA_CF_STEPS", 4000);
  const int subpixels = std::max(2, environmentCount("FEMTO_MEDIA_CF_SUBPIXELS", 8));
  double exact = 0.0, coarser = 0.0;
  for (double v : m.closedFormImageSums(*pathScene, steps, subpixels)) exact += v;
  for (double v : m.closedFormImageSums(*pathScene, steps, subpixels / 2)) coarser += v;
  const double quadrature = std::abs(exact - coarser);
  const bool lightNear = m.lightNearTheView(0.5);
  std::printf("  closed-form window %.5g (+- %.2g)%s\n", exact, quadrature, lightNear ? " (light near the view)" : "");
  for (size_t k = 0; k < b.size(); ++k) {
    const bool window = k + 1 == b.size();
    const int lo = window ? 0 : int(k) * 4, hi = window ? m.grid.bins - 1 : lo + 3;
    double slack = 0.5 * (fine[size_t(hi)] + (hi + 1 < m.grid.bins ? fine[size_t(hi + 1)] : 0.0));
    if (!window) slack += 0.5 * (fine[size_t(lo)] + (lo > 0 ? fine[size_t(lo - 1)] : 0.0));
    const double se =
        std::sqrt(b[k].standardError() * b[k].standardError() + p[k].standardError() * p[k].standardError());
    const double tolerance = 5 * se + boundary * std::abs(p[k].mean()) + slack + 1e-9;
    std::printf("  %s: beams %.5g +- %.2g, path %.5g +- %.2g (beams %+.2f %%), bias bound %.2g, tolerance %.2g %%\n",
                window ? "window" : str("coarse bin ", k).c_str(), b[k].mean(), b[k].standardError(), p[k].mean(),
                p[k].standardError(), 100 * (b[k].mean() / p[k].mean() - 1), boundary * p[k].mean() + slack,
                100 * tolerance / p[k].mean());
    EXPECT_NEAR(b[k].mean(), p[k].mean(), tolerance) << what << (window ? " window" : str(" coarse bin ", k));
    if (!window || lightNear) continue;
    // Both against the closed form: their own noise, the quadrature's error,
    // and for beams the bias bound.
    EXPECT_NEAR(p[k].mean(), exact, 5 * p[k].standardError() + quadrature + 1e-9)
        << what << " path against the closed form";
    EXPECT_NEAR(b[k].mean(), exact, 5 * b[k].standardError() + boundary * exact + slack + quadrature + 1e-9)
        << what << " beams against the closed form";
  }
}

}  // namespace

TEST(TransientBeamsRandomMedia, BeamsAgreeWithPathAndNothingArrivesEarly) {
  const int only = environmentCount("FEMTO_MEDIA_SEED", 0), runs = std::max(2, environmentCount("FEMTO_MEDIA_RUNS", 4));
  const int first = only > 0 ? only : 1, last = only > 0 ? only : environmentCount("FEMTO_MEDIA_SWEEP", 3);
  const int passes = environmentCount("FEMTO_MEDIA_PASSES", 2);
  for (int seed = first; seed <= last; ++seed) checkSeed(seed, runs, passes);
}

// Seeds the sweep (tools/bench/random_media_sweep.sh) once failed, kept in
// CI: 21 (a sphere of eta 1.45 lit from outside: energy before the earliest
// arrival, the extension timed at the wrong index; ray_beam.cpp) and 23 (a
// thin sphere lit from outside: -1.9 % at the planar boundary radius, the
// terminator's loss; boundary_coverage.h). 8 runs of 4 passes: at CI's
// 4 x 2 seed 23's path runs read 12.35 against the closed form's 12.30 (a
// heavy-tailed 3-sigma high), which put a -1.31 % beams window on the 1.3 %
// tolerance's edge; at 8 x 4 beams read -0.44 +- 0.2 % against 1.7 %.
TEST(TransientBeamsRandomMedia, SeedsThatOnceFailed) {
  for (int seed : {21, 23}) checkSeed(seed, 8, 4);
}
