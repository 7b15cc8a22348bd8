// The scenes that reproduce the seed's figures (scenes/seed-*, Marco et al.,
// "Transient Photon Beams"): each loads in strict mode and renders finite
// values at a small size; each one's integrator files (-D integrator=...)
// load strictly and receive its parameters; the glass ball of the caustic scene delays its
// caustic by (eta - 1) 2R; without observer time the first light reaching a
// pixel left the light exactly |light -> visible point| earlier, i.e. the
// wavefronts are centred on the light; the caustic scene's continuous
// emission (-D pulse=continuous) is the running integral of its Dirac
// sequence and ends at the steady image; transient_beams' frames of the
// glass/mirror-balls scene integrate to its steady image. Geometry is probed
// from the loaded scene files, not copied from them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/render/bsdf.h>
#include <femto/render/integrator.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/transport/volumetric.h>
#include <femto/xml/loader.h>

#include "continuous_pulse_check.h"
#include "media_test_util.h"
#include "render_test_util.h"
#include "transient_film_test_util.h"
#include "transient_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::filesystem::path sceneFile(const std::string& name) {
  return std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes" / name / "scene.xml";
}

std::shared_ptr<Scene> loadSeedScene(const std::string& name, std::map<std::string, std::string> defines) {
  LoadOptions options;
  options.strict = true;
  options.defines = std::move(defines);
  return loadScene(sceneFile(name), options);
}

/// Render `scene` to dir/stem.exr and return its volume (h, w, bins filled in).
std::vector<float> renderVolume(const Scene& scene, const std::filesystem::path& dir, const std::string& stem, int& h,
                                int& w, int& bins) {
  RenderOptions render;
  render.output = dir / (stem + ".exr");
  render.progress = false;
  RenderStats stats = scene.integrator().render(scene, render);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u) << "NaN, Inf or negative samples";
  return readVolume(dir / (stem + ".npy"), h, w, bins);
}

/// A rendered transient film: the volume and the steady/before/after images.
struct TransientRender {
  std::vector<float> volume;
  int h = 0, w = 0, bins = 0;
  Bitmap steady, before, after;
  float v(int x, int y, int b, int c) const { return volume[((size_t(y) * w + x) * bins + b) * 3 + c]; }
};

TransientRender renderTransient(const Scene& scene, const std::filesystem::path& dir, const std::string& stem) {
  TransientRender r;
  r.volume = renderVolume(scene, dir, stem, r.h, r.w, r.bins);
  r.steady = readImage(dir / (stem + ".exr"));
  r.before = readImage(dir / (stem + "_before.exr"));
  r.after = readImage(dir / (stem + "_after.exr"));
  return r;
}

/// The brightest value of an image: the scale of float rounding in sums of its contributions.
double brightest(const Bitmap& image) {
  double m = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) m = std::max(m, double(image.pixel(x, y)[c]));
  return m;
}

/// A closed octahedron in the Armadillo's frame (feet at y = -54.2, 151
/// tall), standing in for the mesh so the test needs neither the licensed
/// Armadillo nor Python.
std::filesystem::path writeOctahedron(const std::filesystem::path& dir) {
  auto path = dir / "octahedron.obj";
  std::ofstream out(path);
  out << "v 0 -54.2 0\nv 0 97.1 0\nv -60 21 0\nv 60 21 0\nv 0 21 -60\nv 0 21 60\n"
         "f 1 4 6\nf 1 6 3\nf 1 3 5\nf 1 5 4\nf 2 6 4\nf 2 3 6\nf 2 5 3\nf 2 4 5\n";
  return path;
}

/// Distances along `ray` (up to its tmax) to every surface it crosses that
/// is not an index-matched (pass-through) boundary, nearest first.
std::vector<float> surfacesAlong(const Scene& scene, Ray ray, int maxHits = 16) {
  std::vector<float> ts;
  const Point3f origin = ray.o;
  const float tmax = ray.tmax;
  for (int i = 0; i < 64 && int(ts.size()) < maxHits; ++i) {
    SurfaceInteraction si;
    if (!scene.rayIntersect(ray, si)) break;
    float travelled = distance(origin, si.p);
    if (!isPassThrough(si)) ts.push_back(travelled);
    ray = si.spawnRay(ray.d);
    ray.tmax = tmax - travelled;
  }
  return ts;
}

}  // namespace

TEST(SeedScenes, EachLoadsStrictlyAndRendersFiniteLight) {
  auto dir = scratchDir("seed-scenes");
  // 16 bins of 0.4 cover each scene's default window (6 to 6.4 long).
  const std::map<std::string, std::string> small = {
      {"resolution", "16"}, {"spp", "2"}, {"bins", "16"}, {"bin_width", "0.4"}};
  for (std::string name : {"seed-glass-mirror-balls", "seed-coloured-mirrors-caustic", "seed-glass-armadillo"}) {
    SCOPED_TRACE(name);
    auto defines = small;
    if (name != "seed-glass-mirror-balls") defines["height"] = "12";
    if (name == "seed-glass-armadillo") defines["mesh"] = writeOctahedron(dir).string();
    auto scene = loadSeedScene(name, defines);
    int h = 0, w = 0, bins = 0;
    std::vector<float> volume = renderVolume(*scene, dir, name, h, w, bins);
    ASSERT_EQ(bins, 16);
    double total = 0.0;
    for (float v : volume) {
      ASSERT_TRUE(std::isfinite(v));
      total += v;
    }
    EXPECT_GT(total, 0.0) << "some light arrives inside the default time window";
  }
}

TEST(SeedScenes, EachIntegratorFileReceivesTheSceneParameters) {
  // -D integrator=NAME includes integrator-NAME.xml beside each scene: it must
  // load strictly (every parameter it sets is read) and pass on the scene's
  // max_depth and observer_time, and transient_beams' own parameters.
  auto dir = scratchDir("seed-integrator-files");
  for (std::string name : {"seed-glass-mirror-balls", "seed-coloured-mirrors-caustic", "seed-glass-armadillo"}) {
    SCOPED_TRACE(name);
    std::map<std::string, std::string> defines = {{"max_depth", "7"}, {"observer_time", "false"}};
    if (name == "seed-glass-armadillo") defines["mesh"] = writeOctahedron(dir).string();
    defines["integrator"] = "transient_path";
    std::string path = loadSeedScene(name, defines)->integrator().toString();
    EXPECT_NE(path.find("TransientPathIntegrator["), std::string::npos) << path;
    EXPECT_NE(path.find("max_depth=7,"), std::string::npos) << path;
    EXPECT_NE(path.find("observer_time=false"), std::string::npos) << path;
    defines["integrator"] = "transient_beams";
    defines.insert({{"passes", "3"}, {"photon_count", "1234"}, {"surface_radius", "0.02"}, {"store", "single"}});
    std::string beams = loadSeedScene(name, defines)->integrator().toString();
    for (const char* expected : {"TransientBeamsIntegrator[passes=3,", "photon_count=1234,", "surface_radius=0.02,",
                                 "max_depth=7,", "store=single,", "observer_time=false"})
      EXPECT_NE(beams.find(expected), std::string::npos) << beams << " lacks " << expected;
  }
}

TEST(SeedScenes, ArmadilloSceneFindsTheSharedMeshByDefault) {
  // The default `mesh` is relative to the scene file: ../shared/meshes beside
  // the repository (never committed: research-use licence).
  auto armadillo = std::filesystem::path(FEMTO_SOURCE_DIR) / "../shared/meshes/armadillo.obj";
  if (!std::filesystem::exists(armadillo)) GTEST_SKIP() << "no " << armadillo << " beside the repository";
  auto scene = loadSeedScene("seed-glass-armadillo", {});
  // A ray at mid-height toward the back wall (z = -2.5) meets the figure first (|z| < 0.6).
  std::vector<float> t = surfacesAlong(*scene, Ray(Point3f(0.0f, 0.8f, 3.0f), Vec3f(0, 0, -1)), 1);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_NEAR(t[0], 3.0f, 0.6f) << "the figure stands at the origin";
}

TEST(SeedScenes, GlassBallDelaysTheCausticByEtaMinusOneTimesItsDiameter) {
  // A smaller light sharpens the caustic's arrival; the geometry is otherwise the shipped file's.
  const float eta = 1.5f;
  auto scene = loadSeedScene("seed-coloured-mirrors-caustic", {{"light_radius", "0.03"}, {"ior", "1.5"}});
  // Probe the vertical axis x = z = 0 from above: light (top, bottom), ball (top, bottom), floor.
  const float top = 10.0f;
  std::vector<float> t = surfacesAlong(*scene, Ray(Point3f(0, top, 0), Vec3f(0, -1, 0)), 5);
  ASSERT_EQ(t.size(), 5u) << "light, glass ball and floor on the axis";
  const float lightBottom = top - t[1], ballDiameter = t[3] - t[2], floorY = top - t[4];
  const Point3f caustic(0.0f, floorY, 0.0f);
  const Point3f camera = scene->sensor().toWorld().point(Point3f(0.0f));
  // Along the axis the path is straight (normal incidence), so the only
  // change the ball makes to the optical path length is (eta - 1) 2R.
  const double straight = distance(camera, caustic) + (lightBottom - floorY);
  const double expected = straight + (eta - 1.0) * ballDiameter;
  ASSERT_NEAR(ballDiameter, 1.0f, 1e-3f) << "the scene comment's numbers";

  // Histogram of the light reaching the caustic point along its camera ray,
  // in bins of the shipped film's width.
  const double binWidth = 0.05, lo = straight - 1.0;
  std::vector<double> histogram(60, 0.0);
  auto sampler = seededSampler(21);
  const Ray ray(camera, normalize(caustic - camera));
  for (int i = 0; i < 200000; ++i) {
    CollectingRecorder recorder;
    transientIntegrator(*scene).sample(*scene, ray, *sampler, recorder);
    for (const auto& [opl, value] : recorder.hits) {
      int b = int(std::floor((opl - lo) / binWidth));
      if (b >= 0 && b < int(histogram.size())) histogram[b] += value.g;
    }
  }
  int peak = int(std::max_element(histogram.begin(), histogram.end()) - histogram.begin());
  double peakOpl = lo + (peak + 0.5) * binWidth;
  std::printf("caustic peak at OPL %.3f; straight path %.3f, expected with the glass delay %.3f\n", peakOpl, straight,
              expected);
  ASSERT_GT(histogram[peak], 0.0) << "the caustic is seen by BSDF sampling through the ball";
  EXPECT_NEAR(peakOpl, expected, binWidth);
  // Nothing reaches the caustic point by the straight path: the ball's shadow.
  double early = 0.0;
  for (int b = 0; lo + (b + 1) * binWidth < straight + 0.5 * (eta - 1.0) * ballDiameter; ++b) early += histogram[b];
  EXPECT_LT(early, 0.01 * histogram[peak]);
}

TEST(SeedScenes, WithoutObserverTimeWavefrontsAreCentredOnTheLight) {
  const double start = 0.0, binWidth = 0.1;
  const int res = 16;
  auto scene = loadSeedScene("seed-glass-mirror-balls", {{"observer_time", "false"}, {"start", "0"}, {"bins", "60"},
                                                         {"bin_width", "0.1"}, {"resolution", std::to_string(res)},
                                                         {"spp", "128"}});
  // Probe the light: up from the room's centre hits its bottom, along -x from
  // the right wall its side.
  std::vector<float> up = surfacesAlong(*scene, Ray(Point3f(0, 0, 0), Vec3f(0, 1, 0)), 2);
  std::vector<float> side = surfacesAlong(*scene, Ray(Point3f(0.95f, 0.6f, 0), Vec3f(-1, 0, 0)), 1);
  ASSERT_EQ(up.size(), 2u);
  ASSERT_EQ(side.size(), 1u);
  const float radius = 0.5f * (up[1] - up[0]);
  const Point3f light(0.0f, up[0] + radius, 0.0f);
  ASSERT_NEAR(0.95f - side[0], radius, 1e-3f) << "the light is centred on x = 0 at its height";

  auto dir = scratchDir("seed-observer-time");
  int h = 0, w = 0, bins = 0;
  std::vector<float> volume = renderVolume(*scene, dir, "balls", h, w, bins);
  ASSERT_EQ(w, res);

  // Earliest OPL at which light can reach a point y of a camera ray (without
  // the camera segment): |y - light centre| - radius, at the point of the
  // ray (inside the fog, up to the first surface) nearest the light. Over a
  // pixel, the first arrival lies between the minimum of that over the pixel
  // (3x3 rays: corners, edge midpoints, centre) and its value for the centre
  // ray (samples near the centre come that close).
  const Sensor& sensor = scene->sensor();
  int tested = 0, matched = 0;
  for (int py = 0; py < res; ++py)
    for (int px = 0; px < res; ++px) {
      double nearestMin = Infinity, nearestCentre = Infinity;
      bool usable = true;
      for (float fy : {0.0f, 0.5f, 1.0f})
        for (float fx : {0.0f, 0.5f, 1.0f}) {
          Ray ray;
          sensor.sampleRay(Point2f(px + fx, py + fy), Point2f(0.5f), ray);
          SurfaceInteraction si;
          Ray r = ray;
          float tEnter = -1.0f;
          while (scene->rayIntersect(r, si) && isPassThrough(si)) {
            if (tEnter < 0.0f) tEnter = distance(ray.o, si.p);
            r = si.spawnRay(r.d);
          }
          // Skip pixels that see a ball (light reaches them through glass or
          // a mirror), the light itself, or no fog.
          if (!si.isValid() || si.emitter() || (si.bsdf()->flags() & BSDFFlags::Delta) || tEnter < 0.0f) {
            usable = false;
            continue;
          }
          float tHit = distance(ray.o, si.p);
          float tNear = std::clamp(dot(light - ray.o, ray.d), tEnter, tHit);
          Point3f y = ray(tNear);
          // The nearest point must see the light (no ball in between).
          Ray shadow(y, normalize(light - y), 1e-3f, distance(light, y) - radius - 1e-3f);
          if (!surfacesAlong(*scene, shadow, 1).empty()) usable = false;
          double opl = double(distance(light, y)) - radius;
          nearestMin = std::min(nearestMin, opl);
          if (fx == 0.5f && fy == 0.5f) nearestCentre = opl;
        }
      if (!usable) continue;
      int first = -1;
      for (int b = 0; b < bins && first < 0; ++b)
        for (int c = 0; c < 3; ++c)
          if (volume[((size_t(py) * w + px) * bins + b) * 3 + c] > 0.0f) first = b;
      ASSERT_GE(first, 0) << "pixel " << px << "," << py << " receives light within OPL 6";
      int lowest = int(std::floor((nearestMin - start) / binWidth));
      int centre = int(std::floor((nearestCentre - start) / binWidth));
      ++tested;
      // Nothing arrives before the light could (one bin of slack: the 3x3
      // rays may miss the pixel's exact nearest point by a little).
      EXPECT_GE(first, lowest - 1) << "pixel " << px << "," << py << ": light before it could arrive";
      matched += first <= centre + 1;
    }
  std::printf("%d of %d pixels see their first light within a bin of |light - nearest visible point|\n", matched,
              tested);
  ASSERT_GT(tested, res * res / 3);
  // The first arrival needs a sample near the nearest point; at 128 spp all
  // but a few pixels get one.
  EXPECT_GE(matched, int(0.9 * tested));
}

TEST(SeedScenes, ContinuousEmissionIsTheRunningIntegralOfTheDiracSequenceAndEndsAtTheSteadyImage) {
  // The shipped caustic scene with its light's pulse delta, then continuous,
  // same seed and time axis. complete_steady traces paths past the window, so
  // `after` measures what the window misses: the window (OPL 0 to 96) must
  // outlast every path of max_depth 10 (segments of at most ~9 in this scene).
  // time_splitting off: its time profile, and so its paths, differ between the pulses.
  auto dir = scratchDir("seed-continuous");
  std::map<std::string, std::string> defines = {{"resolution", "16"}, {"height", "12"}, {"spp", "16"},
                                                {"start", "0"},       {"bins", "96"},    {"bin_width", "1"},
                                                {"complete_steady", "true"}, {"time_splitting", "false"}};
  defines["pulse"] = "delta";
  TransientRender dirac = renderTransient(*loadSeedScene("seed-coloured-mirrors-caustic", defines), dir, "dirac");
  defines["pulse"] = "continuous";
  TransientRender step = renderTransient(*loadSeedScene("seed-coloured-mirrors-caustic", defines), dir, "continuous");
  ASSERT_EQ(step.bins, 96);
  const double scale = brightest(dirac.steady);
  ASSERT_GT(scale, 0.0);
  const double slack = 1e-5 * scale + 1e-7;  // float rounding of sums of the same contributions
  for (int y = 0; y < dirac.h; ++y)
    for (int x = 0; x < dirac.w; ++x)
      for (int c = 0; c < 3; ++c) {
        const double steady = dirac.steady.pixel(x, y)[c];
        ASSERT_EQ(dirac.after.pixel(x, y)[c], 0.0f) << "pixel " << x << "," << y << ": light after the window";
        EXPECT_NEAR(step.steady.pixel(x, y)[c], steady, slack) << "the steady image does not depend on the pulse";
        EXPECT_NEAR(step.v(x, y, step.bins - 1, c), steady, slack)
            << "pixel " << x << "," << y << ": the last continuous frame is the steady image";
      }
  EXPECT_TRUE(isRunningIntegralOf(step.volume, dirac.volume, dirac.before, dirac.w, dirac.h, dirac.bins, scale));
}

TEST(SeedScenes, TransientBeamsFramesIntegrateToTheirSteadyImage) {
  // The glass/mirror-balls scene through -D integrator=transient_beams (the
  // photon counts and radii of its integrator-transient_beams.xml; two
  // passes of one camera sample), the window (OPL 0 to 12) covering most of
  // the light: the volume summed over bins plus before and after is the
  // steady image (every beam and photon estimate is deposited exactly).
  auto dir = scratchDir("seed-beams-steady");
  auto scene = loadSeedScene("seed-glass-mirror-balls", {{"integrator", "transient_beams"},
                                                         {"resolution", "12"},
                                                         {"spp", "1"},
                                                         {"passes", "2"},
                                                         {"start", "0"},
                                                         {"bins", "48"},
                                                         {"bin_width", "0.25"}});
  TransientRender r = renderTransient(*scene, dir, "beams");
  const double scale = brightest(r.steady);
  ASSERT_GT(scale, 0.0);
  double inWindow = 0.0, total = 0.0;
  for (int y = 0; y < r.h; ++y)
    for (int x = 0; x < r.w; ++x)
      for (int c = 0; c < 3; ++c) {
        double sum = double(r.before.pixel(x, y)[c]) + r.after.pixel(x, y)[c];
        for (int b = 0; b < r.bins; ++b) sum += r.v(x, y, b, c);
        EXPECT_NEAR(sum, r.steady.pixel(x, y)[c], 1e-5 * scale + 1e-7) << "pixel " << x << "," << y;
        inWindow += sum - r.before.pixel(x, y)[c] - r.after.pixel(x, y)[c];
        total += r.steady.pixel(x, y)[c];
      }
  std::printf("transient_beams: %.1f%% of the steady image arrives inside the window\n", 100.0 * inWindow / total);
  EXPECT_GT(inWindow, 0.5 * total) << "the window holds most of the light, so the sum means something";
}
