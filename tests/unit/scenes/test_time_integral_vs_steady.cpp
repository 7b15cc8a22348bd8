// The time integral of a transient render (sum of the volume's bins plus
// `before` plus `after`, with complete_steady so that light after the window
// is traced too) estimates the same image as a steady render. Checked for
// both transient integrators on the shipped scenes (the fog Cornell box and
// the seed figures' scenes, small), each against an INDEPENDENT steady render:
// the steady `path` integrator on an hdrfilm where the scene has no media,
// transient_path on an hdrfilm (its steady code path: no time axis, no
// horizon) where it has (`path` does not trace media), always with other seeds.
//
// Statistics: every estimate is repeated over `runs` seeds; the image is cut
// into blocks and each block's mean per channel is compared, so an error that
// moves light within the image (a caustic in the wrong place) fails as well as
// one that changes its total. Two estimates agree when their means differ by
// less than Sigmas standard errors of the difference (from the runs' spread:
// transient_beams' noise is mostly its photon maps', shared by all pixels of a
// run, so per-pixel sample variances would understate it) plus, for
// transient_beams, an explicit allowance for its kernel bias (see BeamsBias).
//
// The runs' spread measures the error only if every run sees many of the
// events that carry the light. Light found by rare camera samples (the small
// bright light seen through glass, found by the camera path's specular
// chain, in every integrator alike) is heavy-tailed: with fewer camera
// samples per run than the reference, an estimator's runs miss it and their
// spread does not show it (transient_beams at 8 spp against 128 looked 11 %
// dark at 5 sigma on the Armadillo; at 128 spp it agrees to 0.2 %). So every
// estimate here takes the same camera samples per pixel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <femto/core/plugin.h>
#include <femto/image/image_io.h>
#include <femto/render/emitter.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/xml/loader.h>

#include "media_test_util.h"
#include "render_test_util.h"
#include "transient_agreement_util.h"
#include "transient_film_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

using Defines = std::map<std::string, std::string>;

/// Standard errors of the difference allowed. With 6 runs per estimate the
/// difference's standard error is itself estimated from ~10 degrees of
/// freedom: P(|t_10| > 5) is 5e-4 per compared value.
constexpr double Sigmas = 5.0;

/// transient_beams' kernel-bias allowance: KernelBias (2 % of the value,
/// transient_agreement_util.h), checked here against a measurement on the
/// fog Cornell box (16x16, 2x2 blocks, 16 runs, the same seeds per radius so
/// differences are sharper than the noise): the image mean fell by 0.33 %,
/// 0.72 %, 1.5 % for each doubling of the surface radius from 0.5 % of the
/// scene's diagonal (0.0173) to 4 % (0.138), i.e. linearly in the radius,
/// and by 0.16-0.46 % per doubling of the beam radius from 0.005 to 0.04;
/// the largest block mean fell by 1.0 % from half the default surface radius
/// to the default (1 % of the diagonal, which every test here uses). A bias
/// linear in r is twice what halving r removes: 2 % at the default radii.
/// (On the Armadillo, halving or doubling the surface radius moved the image
/// mean by < 0.3 %.)
constexpr double BeamsBias = KernelBias;

/// transient_beams' own defaults (beam_settings.h: one pass of 100 000
/// photons, derived radii, every camera segment gathering), for the seed
/// scenes, whose integrator-transient_beams.xml holds their figures'
/// settings (more passes and photons, smaller surface radii): BeamsBias was
/// measured at these radii, and the figures' photon counts would make the
/// runs slow.
const Defines BeamsDefaults = {{"passes", "1"},          {"photon_count", "100000"}, {"beam_photon_count", "10000"},
                                {"gather_fraction", "1"}, {"radius", "0"},            {"surface_radius", "0"}};

/// `defines` with BeamsDefaults under them.
Defines withBeamsDefaults(Defines defines) {
  defines.insert(BeamsDefaults.begin(), BeamsDefaults.end());
  return defines;
}

std::shared_ptr<Scene> loadShipped(const std::string& name, const Defines& defines) {
  static bool prepared = [] {
    PluginManager::instance().prependSearchPath(FEMTO_PLUGIN_DIR);
    return true;
  }();
  (void)prepared;
  LoadOptions options;
  options.strict = true;
  options.defines = defines;
  return loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes" / name / "scene.xml", options);
}

/// One render's image as (h, w, 3) doubles: for a transient film the time
/// integral bins + before + after, for a steady film the image itself.
struct Image {
  int w = 0, h = 0;
  std::vector<double> rgb;
  double at(int x, int y, int c) const { return rgb[(size_t(y) * w + x) * 3 + c]; }
};

Image renderImage(const std::shared_ptr<Scene>& scene, const std::filesystem::path& dir, uint64_t seed) {
  const auto out = dir / "out.exr", npy = dir / "out.npy";
  std::filesystem::remove(npy);  // render() reads a volume if there is one: never a stale one
  Rendered r = render(scene, out, seed);
  Image image;
  image.w = r.steady.width, image.h = r.steady.height;
  image.rgb.assign(size_t(image.w) * image.h * 3, 0.0);
  const bool transient = !r.volume.empty();
  Bitmap before, after;
  if (transient) before = readImage(dir / "out_before.exr"), after = readImage(dir / "out_after.exr");
  for (int y = 0; y < image.h; ++y)
    for (int x = 0; x < image.w; ++x)
      for (int c = 0; c < 3; ++c) {
        double& v = image.rgb[(size_t(y) * image.w + x) * 3 + c];
        if (!transient) {
          v = r.steady.pixel(x, y)[c];
          continue;
        }
        v = double(before.pixel(x, y)[c]) + after.pixel(x, y)[c];
        for (int b = 0; b < r.bins; ++b) v += r.volume[((size_t(y) * r.w + x) * r.bins + b) * 3 + c];
      }
  return image;
}

/// Pixels to compare: all but those whose camera rays pass within `radius`
/// of a point light in a medium. Next-event estimation from a medium point
/// at distance d from a point light weighs 1/d^2, so a pixel whose rays pass
/// at distance h has variance ~ 1/h^3 and the image sum's variance
/// (~ integral of h^-3 over the image plane) diverges at h -> 0: the runs'
/// spread would not measure the error. Beyond `radius` it is finite; the mask
/// is the same for every estimator, so they still estimate the same sums.
std::vector<bool> comparedPixels(const Scene& scene, int w, int h, float radius) {
  std::vector<Point3f> lights;
  for (const auto& emitter : scene.emitters()) {
    if (!emitter->isDelta() || emitter->isEnvironment()) continue;
    DirectionSample ds;
    emitter->sampleDirection(Point3f(0.0f), Point2f(0.5f), ds);
    lights.push_back(ds.p);
  }
  std::vector<bool> keep(size_t(w) * h, true);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (float fy : {0.0f, 0.5f, 1.0f})
        for (float fx : {0.0f, 0.5f, 1.0f}) {
          Ray ray;
          scene.sensor().sampleRay(Point2f(x + fx, y + fy), Point2f(0.5f), ray);
          for (const Point3f& light : lights) {
            const Vec3f toLight = light - ray.o;
            const float along = std::max(0.0f, dot(toLight, ray.d));
            if (length(toLight - along * ray.d) < radius) keep[size_t(y) * w + x] = false;
          }
        }
  return keep;
}

/// Per block of a `blocks` x `blocks` grid and channel, the block's mean
/// pixel value (over the compared pixels), and last the whole image's per
/// channel (the sharpest comparison: an error spread over the image shows
/// there first), over `runs` renders with seeds seed0, seed0 + 1, ...
std::vector<Mean> blockMeans(const std::shared_ptr<Scene>& scene, const std::string& name, uint64_t seed0, int runs, int blocks,
                             float lightMargin) {
  auto dir = scratchDir("integral-" + name);
  const int whole = blocks * blocks;
  std::vector<Mean> means(size_t(whole + 1) * 3);
  std::vector<bool> keep;
  for (int run = 0; run < runs; ++run) {
    Image image = renderImage(scene, dir, seed0 + uint64_t(run));
    if (keep.empty()) keep = comparedPixels(*scene, image.w, image.h, lightMargin);
    std::vector<double> sums(means.size(), 0.0), counts(means.size(), 0.0);
    for (int y = 0; y < image.h; ++y)
      for (int x = 0; x < image.w; ++x) {
        if (!keep[size_t(y) * image.w + x]) continue;
        const int block = (y * blocks / image.h) * blocks + x * blocks / image.w;
        for (int c = 0; c < 3; ++c)
          for (int b : {block, whole}) sums[b * 3 + c] += image.at(x, y, c), counts[b * 3 + c] += 1.0;
      }
    for (size_t k = 0; k < means.size(); ++k) means[k].add(counts[k] > 0.0 ? sums[k] / counts[k] : 0.0);
  }
  return means;
}

/// Each mean of `estimate` within Sigmas standard errors of the
/// difference (plus `bias` times the reference value) of `reference`'s.
/// Prints the whole image's differences and the largest, in standard errors.
void expectBlocksAgree(const std::vector<Mean>& estimate, const std::vector<Mean>& reference, const std::string& what,
                 double bias = 0.0) {
  ASSERT_EQ(estimate.size(), reference.size());
  const size_t n = estimate.size();
  std::vector<double> sigmas(n);
  double worst = 0.0;
  for (size_t k = 0; k < n; ++k) {
    const double a = estimate[k].mean(), b = reference[k].mean();
    const double se = std::hypot(estimate[k].standardError(), reference[k].standardError());
    ASSERT_GT(se, 0.0) << what << ": noiseless estimates cannot be told apart from equal ones";
    sigmas[k] = (a - b) / se;
    if (std::abs(sigmas[k]) > std::abs(worst)) worst = sigmas[k];
    EXPECT_NEAR(a, b, Sigmas * se + bias * std::abs(b) + 1e-9)
        << what << (k + 3 >= n ? ", whole image" : str(", block ", k / 3)) << " channel " << k % 3 << ": "
        << sigmas[k] << " standard errors (" << 100.0 * (a / b - 1.0) << " %)";
  }
  std::printf("%s: whole image RGB %+.2f %+.2f %+.2f sigma (%+.2f %% in total), largest of %zu means %+.2f sigma\n",
              what.c_str(), sigmas[n - 3], sigmas[n - 2], sigmas[n - 1],
              100.0 * (estimate[n - 3].mean() + estimate[n - 2].mean() + estimate[n - 1].mean()) /
                      (reference[n - 3].mean() + reference[n - 2].mean() + reference[n - 1].mean()) -
                  100.0,
              n, worst);
}

/// Relative standard error of the whole image's mean (the last three
/// entries, one per channel): how sharp a comparison is.
double relativeError(const std::vector<Mean>& means) {
  double sum = 0.0, var = 0.0;
  for (size_t k = means.size() - 3; k < means.size(); ++k)
    sum += means[k].mean(), var += means[k].standardError() * means[k].standardError();
  return std::sqrt(var) / sum;
}

/// One scene's comparison: transient_path's and transient_beams' time
/// integrals (transient film, complete_steady) against a steady render.
struct Comparison {
  std::string scene;
  Defines common;                   // -D for all renders: size, ...
  Defines window;                   // -D for the transient films only: bins, bin_width, ...
  Defines transientPath, beams;     // -D of each transient integrator's renders
  Defines steady;                   // -D of the reference (film=hdrfilm and its integrator)
  int runs = 6, blocks = 2;
  float lightMargin = 0.0f;         // comparedPixels' radius around point lights
};

void compareWithSteady(const Comparison& c) {
  auto defines = [&](const Defines& own) {
    Defines d = c.common;
    for (const auto& [k, v] : own) d[k] = v;
    return d;
  };
  Defines transient = c.window;
  transient["complete_steady"] = "true";
  Defines tp = defines(c.transientPath), tb = defines(c.beams), st = defines(c.steady);
  tp.merge(Defines(transient)), tb.merge(Defines(transient));
  tp["integrator"] = "transient_path", tb["integrator"] = "transient_beams";
  st["film"] = "hdrfilm";
  // Seeds: each estimate its own range, so no two renders share random numbers.
  // The reference takes twice the camera samples of the transient renders:
  // its noise enters both comparisons.
  auto reference = blockMeans(loadShipped(c.scene, st), c.scene + "-steady", 3000, c.runs, c.blocks, c.lightMargin);
  auto path = blockMeans(loadShipped(c.scene, tp), c.scene + "-tp", 1000, c.runs, c.blocks, c.lightMargin);
  auto beams = blockMeans(loadShipped(c.scene, tb), c.scene + "-tb", 2000, c.runs, c.blocks, c.lightMargin);
  std::printf("%s: relative standard errors of the image mean: steady %.2g, transient_path %.2g, transient_beams %.2g\n",
              c.scene.c_str(), relativeError(reference), relativeError(path), relativeError(beams));
  expectBlocksAgree(path, reference, c.scene + ": transient_path time integral vs steady");
  expectBlocksAgree(beams, reference, c.scene + ": transient_beams time integral vs steady", BeamsBias);
}

}  // namespace

TEST(TimeIntegralVsSteady, FogCornellBox) {
  // The shipped fog box, 8 coarse bins over its window (OPL 3 to 13.24);
  // complete_steady traces the light arriving after it. transient_beams with
  // fewer photons than the scene's default (its noise is mostly the photon
  // maps', shared by all pixels of a run). Reference: transient_path on an
  // hdrfilm (`path` does not trace media). Pixels whose rays pass within 0.5
  // of the point light are left out (comparedPixels: infinite variance).
  Comparison c;
  c.scene = "cornell-box-fog";
  c.common = {{"resolution", "16"}};
  c.window = {{"bins", "8"}, {"bin_width", "1.28"}, {"frames", "false"}};
  c.transientPath = {{"spp", "64"}};
  c.beams = {{"spp", "64"}, {"photon_count", "20000"}};
  c.steady = {{"integrator", "transient_path"}, {"spp", "128"}};
  c.lightMargin = 0.5f;
  c.runs = 8;
  compareWithSteady(c);
}

TEST(TimeIntegralVsSteady, CornellBoxWithoutFogAgainstPath) {
  // The same box without its fog (-D medium=none): the reference is the
  // steady `path` integrator, whose code shares nothing with the transient
  // integrators but the BSDFs, emitters and next-event helpers.
  Comparison c;
  c.scene = "cornell-box-fog";
  c.common = {{"resolution", "16"}, {"medium", "none"}};
  c.window = {{"bins", "8"}, {"bin_width", "1.28"}, {"frames", "false"}};
  c.transientPath = {{"spp", "32"}};
  c.beams = {{"spp", "32"}, {"photon_count", "20000"}};
  c.steady = {{"integrator", "path"}, {"spp", "64"}};
  c.runs = 6;
  compareWithSteady(c);
}

TEST(TimeIntegralVsSteady, SeedGlassMirrorBalls) {
  // Fog, a glass and a mirror ball, a small sphere light (finite variance:
  // no mask). Window OPL 3 to 11 in 8 bins; the reference is transient_path
  // on an hdrfilm (fog). transient_beams with its default photon count and
  // derived radii (BeamsDefaults).
  Comparison c;
  c.scene = "seed-glass-mirror-balls";
  c.common = {{"resolution", "16"}};
  c.window = {{"bins", "8"}, {"bin_width", "1"}};
  c.transientPath = {{"spp", "32"}};
  c.beams = withBeamsDefaults({{"spp", "32"}});
  c.steady = {{"integrator", "transient_path"}, {"spp", "64"}};
  c.runs = 6;
  compareWithSteady(c);
}

TEST(TimeIntegralVsSteady, SeedColouredMirrorsCaustic) {
  // The glass ball's caustic and its reflections in the mirrors. A larger
  // light (radius 0.25 instead of 0.1) so that path tracing, which finds the
  // caustic only by BSDF sampling through the ball onto the light, has a
  // standard error that makes the comparison sharp (a few % per block).
  // No media: the reference is the steady `path` integrator
  // (integrator-path.xml).
  Comparison c;
  c.scene = "seed-coloured-mirrors-caustic";
  c.common = {{"resolution", "16"}, {"height", "12"}, {"light_radius", "0.25"}};
  c.window = {{"bins", "8"}, {"bin_width", "0.75"}};
  c.transientPath = {{"spp", "256"}};
  c.beams = withBeamsDefaults({{"spp", "256"}});
  c.steady = {{"integrator", "path"}, {"spp", "512"}};
  c.runs = 8;
  compareWithSteady(c);
}

TEST(TimeIntegralVsSteady, SeedGlassArmadillo) {
  // The glass figure (max_depth 16: long chains inside the glass). The
  // Stanford Armadillo beside the repository when present (not committed:
  // research-use licence), otherwise the generated fallback creature
  // (tools/scenes/make_blob_mesh.py, level 3: 1280 triangles). No media:
  // the reference is the steady `path` integrator (integrator-path.xml).
  auto dir = scratchDir("integral-armadillo-mesh");
  auto armadillo = std::filesystem::path(FEMTO_SOURCE_DIR) / "../shared/meshes/armadillo.obj";
  std::filesystem::path mesh = armadillo;
  if (!std::filesystem::exists(armadillo)) {
    mesh = dir / "blob.obj";
    const std::string command = "/usr/bin/python3 " +
                                (std::filesystem::path(FEMTO_SOURCE_DIR) / "tools/scenes/make_blob_mesh.py").string() +
                                " " + mesh.string() + " --level 3 > /dev/null";
    if (std::system(command.c_str()) != 0) GTEST_SKIP() << "neither the Armadillo nor Python to make the blob mesh";
  }
  Comparison c;
  c.scene = "seed-glass-armadillo";
  c.common = {{"resolution", "16"}, {"height", "12"}, {"mesh", mesh.string()}};
  c.window = {{"bins", "8"}, {"bin_width", "0.75"}};
  c.transientPath = {{"spp", "128"}};
  c.beams = withBeamsDefaults({{"spp", "128"}});
  c.steady = {{"integrator", "path"}, {"spp", "256"}};
  c.runs = 6;
  compareWithSteady(c);
}

