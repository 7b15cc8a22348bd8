// transient_nlos_path with an nlos_capture_meter: a small hidden Lambertian
// square in front of a Lambertian relay wall, lit by a projector with a tiny
// fov. The third-bounce light (sensor -> wall point w -> square -> lit spot y
// -> laser) must arrive at OPL |s - w| + |w - q| + |q - y| + |y - l| for q on
// the square (confocal: y = w, so 2 |w - q| without the first and last legs;
// exhaustive: ellipsoids with foci w and y), and its radiance must be the
// closed form of three diffuse bounces (Royo et al. 2022, eq. 2 for a point
// spot):
//   L = (rho_w/pi)^2 (rho_p/pi) Phi \int_square cos_yq cos_qy / |q - y|^2
//                                             cos_qw cos_wq / |q - w|^2 dA_q,
// Phi the laser's whole power (all of it lands on the wall).
// filter_depth, discard_direct_paths and account_first_and_last_bounces
// are checked to change exactly what they claim, contribution by contribution.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <femto/render/nlos_sensor.h>

#include "media_test_util.h"
#include "plugin_util.h"
#include "transient_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

const Point3f Origin(1.8f, 0.3f, 0.9f);         // sensor and laser
const Point3f PatchCenter(0.1f, -0.05f, 0.6f);  // the hidden square, facing the wall
const float PatchHalf = 0.05f;  // small: the closed form integrates over it exactly, the spot is a point
const float RhoWall = 0.7f, RhoPatch = 0.6f;
const float Irradiance = 1e7f;  // the projector's, on its plane at distance 1

struct NlosSetup {
  std::string integrator;     // extra integrator parameters
  std::string sensor;         // extra capture-meter parameters
  float fovDegrees = 0.002f;  // the laser's (its spot's size bounds the closed form's bias)
};

std::shared_ptr<Scene> nlosScene(const NlosSetup& s) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_nlos_path">)",
                             s.integrator, R"(</integrator>
  <shape type="rectangle" id="relay_wall">
    <bsdf type="diffuse"><rgb name="reflectance" value=")",
                             RhoWall, R"("/></bsdf>
    <sensor type="nlos_capture_meter">
      <point name="sensor_origin" x="1.8" y="0.3" z="0.9"/>
      <point name="laser_origin" x="1.8" y="0.3" z="0.9"/>)",
                             s.sensor, R"(
      <emitter type="projector"><rgb name="irradiance" value=")",
                             Irradiance, R"("/>
        <float name="fov" value=")",
                             s.fovDegrees, R"("/></emitter>
      <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/><rfilter type="box"/></film>
    </sensor>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value=")",
                             PatchHalf, R"("/><rotate x="1" angle="180"/>
      <translate x="0.1" y="-0.05" z="0.6"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value=")",
                             RhoPatch, R"("/></bsdf>
  </shape>
</scene>)"));
}

const NlosSensor& nlosSensor(const Scene& scene) { return dynamic_cast<const NlosSensor&>(scene.sensor()); }

/// The camera ray of film pixel (i, j) and the wall point it watches.
Ray pixelRay(const Scene& scene, int i, int j, Point3f& watched) {
  Ray ray;
  scene.sensor().sampleRay(Point2f(float(i) + 0.5f, float(j) + 0.5f), Point2f(0.5f), ray);
  SurfaceInteraction si;
  EXPECT_TRUE(scene.rayIntersect(ray, si));
  watched = si.p;
  return ray;
}

/// Points of the square on an n x n midpoint grid, each with its area.
template <typename F>
void overPatch(int n, F&& f) {
  float h = 2.0f * PatchHalf / float(n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      f(Point3f(PatchCenter.x - PatchHalf + (float(a) + 0.5f) * h, PatchCenter.y - PatchHalf + (float(b) + 0.5f) * h,
                PatchCenter.z),
        h * h);
}

/// The closed form above, by a fine midpoint rule over the square (its error
/// is far below the Monte Carlo noise: the integrand is smooth there).
double thirdBounceRadiance(const Point3f& w, const Point3f& y, float fovDegrees) {
  double tanHalf = std::tan(double(fovDegrees) * Pi / 360.0);
  double power = double(Irradiance) * 4.0 * tanHalf * tanHalf;  // irradiance times the plane's area
  double integral = 0.0;
  overPatch(200, [&](const Point3f& q, float area) {
    // The wall's normal is +z, the square's -z.
    Vec3f qy = y - q, qw = w - q;
    double ry2 = dot(qy, qy), rw2 = dot(qw, qw);
    double cosY = q.z / std::sqrt(ry2), cosW = q.z / std::sqrt(rw2);  // both ends see the same height
    integral += area * (cosY * cosY / ry2) * (cosW * cosW / rw2);
  });
  return double(RhoWall) * RhoWall * RhoPatch / (Pi * Pi * Pi) * power * integral;
}

/// How far the spot's points lie from the aimed point: the projector's square
/// frustum (half-angle fov/2 on each axis) meets the wall at most this far.
float spotRadius(const Point3f& target, float fovDegrees) {
  Vec3f d = target - Origin;
  float cosIncidence = std::abs(d.z) / length(d);
  return length(d) * std::tan(degToRad(fovDegrees) * 0.5f) * std::sqrt(2.0f) / (cosIncidence * cosIncidence);
}

/// [min, max] of |w - q| + |q - y| over the square: a convex function of q,
/// so its maximum is at a corner; the minimum from a fine grid, less the
/// grid's reach (the function is 2-Lipschitz, cells are h wide).
std::pair<double, double> ellipsoidRange(const Point3f& w, const Point3f& y) {
  double lo = Infinity, hi = 0.0;
  const int n = 400;
  overPatch(n, [&](const Point3f& q, float) { lo = std::min(lo, double(distance(w, q) + distance(q, y))); });
  lo -= 2.0 * std::sqrt(2.0) * PatchHalf / n;
  for (float sx : {-1.0f, 1.0f})
    for (float sy : {-1.0f, 1.0f}) {
      Point3f q(PatchCenter.x + sx * PatchHalf, PatchCenter.y + sy * PatchHalf, PatchCenter.z);
      hi = std::max(hi, double(distance(w, q) + distance(q, y)));
    }
  return {lo, hi};
}

/// Renders `samples` camera samples of pixel (i, j), third bounce only, and
/// checks every arrival against the ellipsoid range and the mean against
/// the closed form.
void checkThirdBounce(const NlosSetup& setup, bool accounted, int i, int j, int samples) {
  auto scene = nlosScene(setup);
  const NlosSensor& sensor = nlosSensor(*scene);
  Point3f w;
  Ray ray = pixelRay(*scene, i, j, w);
  Point3f y = sensor.laserTarget(w);
  auto [lo, hi] = ellipsoidRange(w, y);
  // Moving the lit point within the spot changes |q - y| + |y - l| by at most twice its distance.
  double slack = 2.0 * spotRadius(y, setup.fovDegrees) + 1e-5;
  double legs = accounted ? distance(Origin, w) + distance(Origin, y) : 0.0;
  auto sampler = seededSampler(uint64_t(7 + i + 10 * j));
  Mean radiance;
  size_t hits = 0;
  for (int n = 0; n < samples; ++n) {
    CollectingRecorder recorder;
    transientIntegrator(*scene).sample(*scene, ray, *sampler, recorder);
    double sum = 0.0;
    for (const auto& [opl, value] : recorder.hits) {
      ++hits;
      ASSERT_GE(opl, legs + lo - slack) << "pixel " << i << "," << j;
      ASSERT_LE(opl, legs + hi + slack) << "pixel " << i << "," << j;
      sum += value.g;
    }
    radiance.add(sum);
  }
  ASSERT_GT(hits, size_t(samples) / 2);
  double expected = thirdBounceRadiance(w, y, setup.fovDegrees);
  // Bias of the point-spot closed form: the geometric factors change by at
  // most ~ (2 + 2) / r relative per unit move of y or w (inverse square and
  // two cosines), r >= the square's height; y moves within the spot, and
  // rays leave w from an origin offset off the wall (RayEpsilon, scaled by
  // the point's magnitude: SurfaceInteraction::offsetOrigin).
  double offset = RayEpsilon * (1.0f + std::max(std::abs(w.x), std::abs(w.y)));
  double bias = 4.0 * (spotRadius(y, setup.fovDegrees) + offset) / PatchCenter.z * expected;
  EXPECT_NEAR(radiance.mean(), expected, 5.0 * radiance.standardError() + bias)
      << "pixel " << i << "," << j << ", standard error " << radiance.standardError();
}

const char* ThirdBounceSampling = R"(<integer name="filter_depth" value="4"/>
    <boolean name="nlos_laser_sampling" value="true"/><boolean name="nlos_hidden_geometry_sampling" value="true"/>)";

/// Every contribution of `samples` camera samples of pixel (i, j), sorted.
/// Each sample starts its own random stream (as the render loop's samples
/// do), so a path cut short by a filter leaves the other samples unchanged.
std::vector<std::pair<double, Color3f>> contributions(const Scene& scene, int i, int j, int samples) {
  Point3f w;
  Ray ray = pixelRay(scene, i, j, w);
  auto sampler = seededSampler(11);
  std::vector<std::pair<double, Color3f>> all;
  for (int n = 0; n < samples; ++n) {
    sampler->startPixel(11, uint64_t(n));
    CollectingRecorder recorder;
    transientIntegrator(scene).sample(scene, ray, *sampler, recorder);
    all.insert(all.end(), recorder.hits.begin(), recorder.hits.end());
  }
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second.g < b.second.g;
  });
  return all;
}

const char* AllDepths = R"(<integer name="max_depth" value="6"/><boolean name="nlos_laser_sampling" value="true"/>)";
const char* Confocal = R"(<boolean name="confocal" value="true"/>)";

}  // namespace

TEST(TransientNlosPath, ConfocalThirdBounceArrivesAtTwiceTheDistanceWithTheClosedFormRadiance) {
  for (bool accounted : {true, false}) {
    SCOPED_TRACE(accounted ? "first and last legs accounted" : "first and last legs removed");
    NlosSetup setup{ThirdBounceSampling, str(Confocal, "<boolean name=\"account_first_and_last_bounces\" value=\"",
                                             accounted ? "true" : "false", "\"/>")};
    for (auto [i, j] : {std::pair{0, 0}, std::pair{1, 2}, std::pair{3, 1}})
      checkThirdBounce(setup, accounted, i, j, 16000);
  }
}

TEST(TransientNlosPath, ExhaustiveThirdBounceFollowsTheEllipsoidsOfWatchedAndLitPoints) {
  NlosSetup setup{ThirdBounceSampling, R"(<point name="laser_lookat_3d" x="-0.4" y="0.3" z="0"/>)"};
  for (auto [i, j] : {std::pair{0, 3}, std::pair{2, 2}, std::pair{3, 0}}) checkThirdBounce(setup, true, i, j, 4000);
  // laser_lookat_pixel names the same kind of point in film pixels: pixel (1, 2)'s centre.
  auto scene = nlosScene({ThirdBounceSampling, R"(<point name="laser_lookat_pixel" x="1.5" y="2.5" z="0"/>)"});
  Point3f w;
  pixelRay(*scene, 1, 2, w);
  Point3f target = nlosSensor(*scene).laserTarget(Point3f(5.0f));
  EXPECT_NEAR(distance(target, w), 0.0f, 1e-5f);
}

// With the same seed, the contributions of filter_depth = 2 ... 6 are those of
// the unfiltered render, split by depth; discard_direct_paths drops exactly
// the depth-2 ones, which arrive confocally at 2 |s - w|.
TEST(TransientNlosPath, FilterDepthAndDiscardDirectPathsKeepExactlyTheirPaths) {
  NlosSetup all{AllDepths, Confocal, 3.0f};
  auto full = contributions(*nlosScene(all), 2, 1, 400);
  std::vector<std::pair<double, Color3f>> split, direct;
  for (int depth = 2; depth <= 6; ++depth) {
    auto part = contributions(
        *nlosScene({str(AllDepths, "<integer name=\"filter_depth\" value=\"", depth, "\"/>"), Confocal, 3.0f}), 2, 1,
        400);
    if (depth == 2)
      direct = part;
    else if (depth == 4)
      EXPECT_FALSE(part.empty()) << "no third bounce";
    split.insert(split.end(), part.begin(), part.end());
  }
  std::sort(split.begin(), split.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first < b.first : a.second.g < b.second.g;
  });
  ASSERT_EQ(split.size(), full.size());
  for (size_t k = 0; k < full.size(); ++k) {
    EXPECT_EQ(split[k].first, full[k].first);
    EXPECT_EQ(split[k].second, full[k].second);
  }
  ASSERT_EQ(direct.size(), 400u) << "the lit wall point is seen by every camera sample";
  Point3f w;
  pixelRay(*nlosScene(all), 2, 1, w);
  for (const auto& [opl, value] : direct) EXPECT_NEAR(opl, 2.0 * distance(Origin, w), 1e-5);

  auto discarded = contributions(
      *nlosScene({str(AllDepths, R"(<boolean name="discard_direct_paths" value="true"/>)"), Confocal, 3.0f}), 2, 1,
      400);
  EXPECT_EQ(discarded.size(), full.size() - direct.size());
  for (const auto& c : discarded)
    EXPECT_TRUE(std::find(direct.begin(), direct.end(), c) == direct.end()) << "a direct path was kept at " << c.first;
}

// account_first_and_last_bounces = false moves every contribution earlier by
// |s - w| + |l - y| and changes nothing else.
TEST(TransientNlosPath, UnaccountedLegsShiftEveryContributionByBothLegs) {
  // Hidden-geometry sampling (mixed with BSDF sampling) finds the square from every wall point.
  const std::string integrator = str(AllDepths, R"(<boolean name="nlos_hidden_geometry_sampling" value="true"/>
    <boolean name="nlos_hidden_geometry_sampling_do_rroulette" value="true"/>)");
  for (const char* aim : {Confocal, R"(<point name="laser_lookat_3d" x="-0.4" y="0.3" z="0"/>)"}) {
    SCOPED_TRACE(aim);
    auto accounted = nlosScene({integrator, aim, 3.0f});
    auto unaccounted =
        nlosScene({integrator, str(aim, R"(<boolean name="account_first_and_last_bounces" value="false"/>)"), 3.0f});
    auto a = contributions(*accounted, 1, 3, 200), b = contributions(*unaccounted, 1, 3, 200);
    Point3f w;
    pixelRay(*accounted, 1, 3, w);
    double legs = distance(Origin, w) + distance(Origin, nlosSensor(*accounted).laserTarget(w));
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    for (size_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(b[k].first, a[k].first - legs, 1e-9 * a[k].first);
      EXPECT_EQ(b[k].second, a[k].second);
    }
  }
}

TEST(TransientNlosPath, ThroughACameraMatchesTheCaptureMeter) {
  // mitransient's NLOS example: an ordinary camera sees the relay wall and
  // the projector is placed by the scene, aimed with its own look-at. With
  // the camera where the capture meter's sensor sits, looking at the point a
  // meter pixel watches, and the projector where the meter aims its laser,
  // the same camera ray gets the same third-bounce light (legs kept in both;
  // laser sampling, BSDF directions: the hidden geometry is not sampled, as
  // through a camera it would include the wall).
  const char* integrator = R"(<integer name="filter_depth" value="4"/><boolean name="nlos_laser_sampling" value="true"/>)";
  auto meter = nlosScene({integrator, R"(<point name="laser_lookat_3d" x="-0.2" y="0.1" z="0"/>)", 0.002f});
  Point3f w;
  pixelRay(*meter, 2, 1, w);
  auto camera = loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_nlos_path">)", integrator, R"(</integrator>
  <sensor type="perspective"><float name="fov" value="0.01"/>
    <transform name="to_world"><lookat origin="1.8, 0.3, 0.9" target=")", w.x, ", ", w.y, ", ", w.z,
                                    R"(" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="1"/><integer name="height" value="1"/></film></sensor>
  <emitter type="projector"><rgb name="irradiance" value=")", Irradiance, R"("/><float name="fov" value="0.002"/>
    <transform name="to_world"><lookat origin="1.8, 0.3, 0.9" target="-0.2, 0.1, 0" up="0, 1, 0"/></transform></emitter>
  <shape type="rectangle">
    <bsdf type="diffuse"><rgb name="reflectance" value=")", RhoWall, R"("/></bsdf>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value=")", PatchHalf, R"("/><rotate x="1" angle="180"/>
      <translate x="0.1" y="-0.05" z="0.6"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", RhoPatch, R"("/></bsdf>
  </shape>
</scene>)"));
  RenderOptions options;
  options.progress = false;
  camera->integrator().render(*camera, options);  // the set-up checks pass (the laser points at the scene)
  auto a = contributions(*meter, 2, 1, 2000);
  // The same ray, through the camera scene's integrator.
  Ray ray;
  meter->sensor().sampleRay(Point2f(2.5f, 1.5f), Point2f(0.5f), ray);
  auto sampler = seededSampler(11);
  std::vector<std::pair<double, Color3f>> b;
  for (int n = 0; n < 2000; ++n) {
    sampler->startPixel(11, uint64_t(n));
    CollectingRecorder recorder;
    transientIntegrator(*camera).sample(*camera, ray, *sampler, recorder);
    b.insert(b.end(), recorder.hits.begin(), recorder.hits.end());
  }
  std::sort(b.begin(), b.end(), [](const auto& x, const auto& y) {
    return x.first != y.first ? x.first < y.first : x.second.g < y.second.g;
  });
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  double sumA = 0.0, sumB = 0.0;
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k].first, b[k].first, 1e-4 * a[k].first);
    sumA += a[k].second.g, sumB += b[k].second.g;
  }
  EXPECT_NEAR(sumA, sumB, 1e-3 * sumA);
}

TEST(TransientNlosPath, ThroughACameraUnaccountedLegsShiftByBothLegs) {
  // account_first_and_last_bounces = false on the integrator (there is no
  // capture meter): every contribution moves earlier by the camera-to-wall
  // leg and the laser-to-lit-point leg (the projector's axis meets the wall
  // at its target).
  auto scene = [](bool keep) {
    return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_nlos_path"><integer name="filter_depth" value="4"/>
    <boolean name="nlos_laser_sampling" value="true"/>
    <boolean name="account_first_and_last_bounces" value=")", keep ? "true" : "false", R"("/></integrator>
  <sensor type="perspective"><float name="fov" value="0.01"/>
    <transform name="to_world"><lookat origin="1.8, 0.3, 0.9" target="0.3, -0.2, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="1"/><integer name="height" value="1"/></film></sensor>
  <emitter type="projector"><rgb name="irradiance" value="1e7"/><float name="fov" value="0.002"/>
    <transform name="to_world"><lookat origin="1.8, 0.3, 0.9" target="-0.2, 0.1, 0" up="0, 1, 0"/></transform></emitter>
  <shape type="rectangle"><bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="0.05"/><rotate x="1" angle="180"/>
      <translate x="0.1" y="-0.05" z="0.6"/></transform><bsdf type="diffuse"/></shape>
</scene>)"));
  };
  auto kept = scene(true), removed = scene(false);
  Ray ray;
  kept->sensor().sampleRay(Point2f(0.5f), Point2f(0.5f), ray);
  SurfaceInteraction wall;
  ASSERT_TRUE(kept->rayIntersect(ray, wall));
  const double legs = wall.t + distance(Origin, Point3f(-0.2f, 0.1f, 0.0f));
  auto collect = [&](const Scene& s) {
    auto sampler = seededSampler(5);
    std::vector<std::pair<double, Color3f>> hits;
    for (int n = 0; n < 300; ++n) {
      sampler->startPixel(5, uint64_t(n));
      CollectingRecorder recorder;
      transientIntegrator(s).sample(s, ray, *sampler, recorder);
      hits.insert(hits.end(), recorder.hits.begin(), recorder.hits.end());
    }
    return hits;
  };
  auto a = collect(*kept), b = collect(*removed);
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  for (size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(b[k].first, a[k].first - legs, 1e-4 * a[k].first);
}

// Laser sampling and hidden-geometry sampling are other estimators of the
// same integral as plain path tracing (BSDF sampling, next-event estimation
// to the laser): with a spot wide enough for BSDF sampling to find it, all
// four combinations agree within their noise, at every arrival time alike
// (the steady sum and the mean OPL are compared). Pure hidden-geometry
// sampling without laser sampling finds nothing: without the relay wall
// among the hidden geometry its paths never return to the wall
// (mitransient's documented omission).
TEST(TransientNlosPath, LaserAndHiddenGeometrySamplingAgreeWithPlainPathTracing) {
  const char* depth4 = R"(<integer name="filter_depth" value="4"/>)";
  const char* ls = R"(<boolean name="nlos_laser_sampling" value="true"/>)";
  const char* hg = R"(<boolean name="nlos_hidden_geometry_sampling" value="true"/>)";
  const char* mix = R"(<boolean name="nlos_hidden_geometry_sampling" value="true"/>
    <boolean name="nlos_hidden_geometry_sampling_do_rroulette" value="true"/>)";
  struct Variant {
    std::string params;
    int samples;
  };
  // Fewer samples where every path contributes.
  std::vector<Variant> variants = {{str(depth4, ls, hg), 80000},
                                   {str(depth4, mix), 400000},
                                   {str(depth4, hg), 2000},
                                   {str(depth4, ls, mix), 40000},
                                   {str(depth4, ls), 200000}};
  std::vector<Mean> radiance(variants.size()), opl(variants.size());
  for (size_t v = 0; v < variants.size(); ++v) {
    auto scene = nlosScene({variants[v].params, R"(<point name="laser_lookat_3d" x="-0.2" y="0.1" z="0"/>)", 25.0f});
    Point3f w;
    Ray ray = pixelRay(*scene, 1, 1, w);
    auto sampler = seededSampler(21 + v);
    for (int n = 0; n < variants[v].samples; ++n) {
      CollectingRecorder recorder;
      transientIntegrator(*scene).sample(*scene, ray, *sampler, recorder);
      double sum = 0.0, weighted = 0.0;
      for (const auto& [t, value] : recorder.hits) sum += value.g, weighted += t * value.g;
      radiance[v].add(sum);
      opl[v].add(weighted);
    }
  }
  for (size_t v = 1; v < variants.size(); ++v) {
    SCOPED_TRACE(variants[v].params);
    if (variants[v].params == str(depth4, hg)) {
      EXPECT_EQ(radiance[v].mean(), 0.0);
      continue;
    }
    double se = std::hypot(radiance[0].standardError(), radiance[v].standardError());
    EXPECT_NEAR(radiance[v].mean(), radiance[0].mean(), 5.0 * se) << "standard error " << se;
    double seOpl = std::hypot(opl[0].standardError(), opl[v].standardError());
    EXPECT_NEAR(opl[v].mean(), opl[0].mean(), 5.0 * seOpl) << "radiance-weighted OPL, standard error " << seOpl;
    EXPECT_GT(radiance[v].mean(), 10.0 * se) << "too few paths found the light to compare";
  }
}

// A capture is a function of the scene and the seed, whatever the thread
// count: the .npy of a 1-thread and a 2-thread render are the same bytes.
TEST(TransientNlosPath, CaptureIsTheSameForAnyThreadCount) {
  auto scene = loadSceneStrict(R"(<scene version="3.0.0">
  <integrator type="transient_nlos_path"><boolean name="nlos_laser_sampling" value="true"/>
    <boolean name="nlos_hidden_geometry_sampling" value="true"/>
    <boolean name="nlos_hidden_geometry_sampling_do_rroulette" value="true"/></integrator>
  <shape type="rectangle">
    <sensor type="nlos_capture_meter">
      <point name="sensor_origin" x="1.8" y="0.3" z="0.9"/><boolean name="confocal" value="true"/>
      <emitter type="projector"><float name="fov" value="0.5"/></emitter>
      <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
      <film type="transient_hdr_film"><integer name="width" value="16"/><integer name="height" value="16"/>
        <integer name="temporal_bins" value="64"/><float name="bin_width_opl" value="0.05"/><float name="start_opl" value="3"/>
        <boolean name="write_frames" value="false"/><rfilter type="box"/></film>
    </sensor>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.2"/><rotate x="1" angle="180"/><translate z="0.6"/></transform>
  </shape>
</scene>)");
  auto dir = std::filesystem::temp_directory_path() / str("femto-nlos-threads-", ::getpid());
  std::filesystem::create_directories(dir);
  std::string bytes[2];
  for (int threads : {1, 2}) {
    RenderOptions options;
    options.output = dir / str("capture", threads, ".exr");
    options.progress = false;
    options.threads = threads;
    options.seed = 5;
    scene->integrator().render(*scene, options);
    auto npy = options.output;
    npy.replace_extension(".npy");
    std::ifstream in(npy, std::ios::binary);
    bytes[threads - 1] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  std::filesystem::remove_all(dir);
  ASSERT_GT(bytes[0].size(), 16u * 16u * 64u * 3u * 4u);
  EXPECT_NE(bytes[0].find_first_not_of('\0', 128), std::string::npos) << "a black capture";
  EXPECT_TRUE(bytes[0] == bytes[1]) << "the 1-thread and 2-thread captures differ";
}
