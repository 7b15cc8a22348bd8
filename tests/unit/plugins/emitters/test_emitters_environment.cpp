// Environment emitters (constant, envmap) and the directional light:
// sampling checked against the claimed densities with chi-square tests,
// envmap against the constant emitter and its lat-long convention, emitted
// rays against the scene's bounding sphere, and renders by the path
// integrator against closed forms (a diffuse sphere under a uniform sky, a
// plane under a directional light).
#include <gtest/gtest.h>

#include <numeric>

#include <femto/image/image_io.h>
#include <femto/math/warp.h>
#include <femto/render/emitter.h>
#include <femto/render/scene.h>

#include "chi2.h"
#include "expect_color.h"
#include "li_estimate.h"
#include "render_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int ChiSquareTests = 4;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

/// A scene holding one emitter (given as XML) and a small cube centred at
/// (1, 2, 3) with half-size 0.5, so the bounding sphere is known.
std::shared_ptr<Scene> sceneWith(const std::string& emitterXml) {
  return loadStrict(str(R"(<scene version="3.0.0">
  <shape type="cube">
    <transform name="to_world"><scale value="0.5"/><translate x="1" y="2" z="3"/></transform>
  </shape>
  )", emitterXml, R"(
</scene>)"));
}
const Point3f SphereCenter(1, 2, 3);
const float SphereRadius = 0.5f * std::sqrt(3.0f);

const Emitter& onlyEmitter(const Scene& scene) {
  EXPECT_EQ(scene.emitters().size(), 1u);
  return *scene.emitters().front();
}

/// Chi-square test of sampleDirection's directions against pdfDirection.
ChiSquareResult testDirectionSampling(const Emitter& emitter, const Point3f& ref) {
  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) {
    DirectionSample ds;
    emitter.sampleDirection(ref, u, ds);
    return ds.d;
  };
  std::function<double(const Vec3f&)> pdf = [&](const Vec3f& d) {
    DirectionSample ds;
    ds.d = d;
    ds.dist = Infinity;
    return emitter.pdfDirection(ref, ds);
  };
  return testSampler<Vec3f>(sphericalDomain(32, 64), sample, pdf, 500000, 16);
}

/// Every sample: value * pdf is the radiance the emitter shows along ds.d,
/// and ds.pdf is what pdfDirection reports.
void expectSamplesConsistent(const Emitter& emitter, const Point3f& ref) {
  PCG32 rng(11, 13);
  for (int i = 0; i < 500; ++i) {
    DirectionSample ds;
    Color3f value = emitter.sampleDirection(ref, {rng.nextFloat(), rng.nextFloat()}, ds);
    if (ds.pdf == 0.0f) continue;
    EXPECT_EQ(ds.dist, Infinity);
    EXPECT_NEAR(length(ds.d), 1.0f, 1e-5f);
    EXPECT_NEAR(emitter.pdfDirection(ref, ds), ds.pdf, 1e-3f * ds.pdf);
    expectColorNear(value * ds.pdf, emitter.evalEnvironment(Ray(ref, ds.d)), 1e-4f);
  }
}

/// Emitted rays must cross the scene's bounding sphere (so photons reach the scene).
void expectRaysCrossTheBoundingSphere(const Emitter& emitter) {
  PCG32 rng(2, 9);
  for (int i = 0; i < 200; ++i) {
    Ray ray;
    Color3f weight = emitter.sampleRay({rng.nextFloat(), rng.nextFloat()}, {rng.nextFloat(), rng.nextFloat()}, ray);
    EXPECT_TRUE(weight.isValid());
    Vec3f toCenter = SphereCenter - ray.o;
    float along = dot(toCenter, ray.d);
    EXPECT_GT(along, 0.0f);  // the sphere lies ahead
    EXPECT_LE(length(toCenter - ray.d * along), SphereRadius * (1.0f + 1e-4f));
  }
}

/// Write a lat-long map whose texel (x, y) is f(x, y); returns its path.
template <typename F>
std::filesystem::path writeMap(const std::filesystem::path& dir, const std::string& name, int w, int h, F&& f) {
  Bitmap image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Color3f c = f(x, y);
      for (int k = 0; k < 3; ++k) image.pixel(x, y)[k] = c[k];
    }
  auto path = dir / name;
  writeEXR(path, image);
  return path;
}

std::string envmapXml(const std::filesystem::path& file, float scale = 1.0f, const std::string& extra = "") {
  return str(R"(<emitter type="envmap"><string name="filename" value=")", file.string(), R"("/><float name="scale" value=")",
             scale, R"("/>)", extra, "</emitter>");
}

class EnvironmentMapTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratchDir("envmap"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

/// A map with structure: a smooth gradient, a bright spot and a black band.
Color3f structuredTexel(int x, int y) {
  if (y == 5) return Color3f(0.0f);
  float base = 0.2f + 0.05f * float(x % 7) + 0.1f * float(y);
  if (x >= 20 && x < 23 && y >= 2 && y < 4) return Color3f(30.0f, 20.0f, 10.0f);
  return Color3f(base, 0.5f * base, 2.0f * base);
}

}  // namespace

TEST(ConstantEmitter, SamplesTheSphereUniformlyAndReturnsRadianceOverPdf) {
  const Color3f L(0.5f, 1.0f, 2.0f);
  auto scene = sceneWith(str(R"(<emitter type="constant"><rgb name="radiance" value=")", rgb(L), R"("/></emitter>)"));
  const Emitter& emitter = onlyEmitter(*scene);
  EXPECT_TRUE(emitter.isEnvironment());
  EXPECT_FALSE(emitter.isDelta());
  ChiSquareResult r = testDirectionSampling(emitter, {0.2f, 0.1f, -0.3f});
  EXPECT_GT(r.pValue, Significance) << r.message;
  expectSamplesConsistent(emitter, {1.0f, 2.0f, 3.0f});
  expectColorNear(scene->evalEnvironment(Ray({0, 0, 0}, normalize(Vec3f(1, -2, 3)))), L, 1e-5f);
}

TEST(ConstantEmitter, EmitsRaysIntoTheSceneWithItsPower) {
  const Color3f L(0.5f, 1.0f, 2.0f);
  auto scene = sceneWith(str(R"(<emitter type="constant"><rgb name="radiance" value=")", rgb(L), R"("/></emitter>)"));
  const Emitter& emitter = onlyEmitter(*scene);
  // Flux into the bounding sphere: L pi (4 pi R^2).
  expectColorNear(emitter.power(), L * (4.0f * Pi * Pi * SphereRadius * SphereRadius), 1e-5f);
  expectRaysCrossTheBoundingSphere(emitter);
  // Emitted directions are uniform over the sphere.
  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) {
    Ray ray;
    emitter.sampleRay({0.4f, 0.6f}, u, ray);
    return ray.d;
  };
  std::function<double(const Vec3f&)> pdf = [](const Vec3f&) { return double(Inv4Pi); };
  ChiSquareResult r = testSampler<Vec3f>(sphericalDomain(16, 32), sample, pdf, 200000, 4);
  EXPECT_GT(r.pValue, Significance) << r.message;
}

TEST(ConstantEmitter, ConvexDiffuseObjectReflectsAlbedoTimesRadiance) {
  // Under uniform illumination a convex object never sees itself, so its
  // outgoing radiance is exactly rho L at every point, at any depth.
  const Color3f rho(0.2f, 0.5f, 0.8f), L(1.0f, 2.0f, 0.5f);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"/>
  <shape type="sphere">
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(rho), R"("/></bsdf>
  </shape>
  <emitter type="constant"><rgb name="radiance" value=")", rgb(L), R"("/></emitter>
</scene>)"));
  Estimate e = estimateLi(*scene, 20000, [](PCG32& rng) {
    // From random points 4 units away toward random points of the sphere's inner half.
    Point3f o = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()}) * 4.0f;
    Point3f target = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()}) * 0.5f;
    return Ray(o, normalize(target - o));
  });
  expectWithinErrorBars(e, rho * L);
  // A ray that misses sees the sky itself.
  expectWithinErrorBars(estimateLi(*scene, 10, [](PCG32&) { return Ray({0, 0, 4}, {0, 0, 1}); }), L);
}

TEST_F(EnvironmentMapTest, AConstantMapEqualsTheConstantEmitter) {
  const Color3f value(0.3f, 0.6f, 0.9f);
  const float scale = 2.5f;
  auto map = writeMap(dir_, "grey.exr", 16, 8, [&](int, int) { return value; });
  auto envScene = sceneWith(envmapXml(map, scale));
  auto constScene =
      sceneWith(str(R"(<emitter type="constant"><rgb name="radiance" value=")", rgb(value * scale), R"("/></emitter>)"));
  const Emitter &env = onlyEmitter(*envScene), &constant = onlyEmitter(*constScene);
  PCG32 rng(4, 4);
  const Point3f ref(0.5f, 0.5f, 0.5f);
  for (int i = 0; i < 200; ++i) {
    Vec3f d = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()});
    expectColorNear(env.evalEnvironment(Ray(ref, d)), constant.evalEnvironment(Ray(ref, d)), 1e-5f);
    DirectionSample ds;
    ds.d = d;
    ds.dist = Infinity;
    EXPECT_NEAR(env.pdfDirection(ref, ds), Inv4Pi, 1e-4f * Inv4Pi);
    Color3f sampled = env.sampleDirection(ref, {rng.nextFloat(), rng.nextFloat()}, ds);
    EXPECT_NEAR(ds.pdf, Inv4Pi, 1e-4f * Inv4Pi);
    expectColorNear(sampled, value * scale * (4.0f * Pi), 1e-4f);
  }
  expectColorNear(env.power(), constant.power(), 1e-4f);
}

TEST_F(EnvironmentMapTest, SamplingMatchesItsPdf) {
  auto map = writeMap(dir_, "structured.exr", 32, 16, structuredTexel);
  auto scene = sceneWith(envmapXml(map, 1.0f, R"(<transform name="to_world"><rotate x="1" y="1" angle="40"/></transform>)"));
  const Emitter& env = onlyEmitter(*scene);
  ChiSquareResult r = testDirectionSampling(env, {0, 0, 0});
  EXPECT_GT(r.pValue, Significance) << r.message;
  expectSamplesConsistent(env, {0.3f, 0.0f, 1.0f});
  // The density integrates to one over the sphere.
  std::function<double(const Vec3f&)> pdf = [&](const Vec3f& d) {
    DirectionSample ds;
    ds.d = d;
    ds.dist = Infinity;
    return env.pdfDirection({0, 0, 0}, ds);
  };
  std::vector<double> cells = integrateCells(sphericalDomain(64, 128), pdf, 4);
  EXPECT_NEAR(std::accumulate(cells.begin(), cells.end(), 0.0), 1.0, 5e-3);
}

TEST_F(EnvironmentMapTest, EmittedRaysFollowTheMapAndItsPower) {
  auto map = writeMap(dir_, "structured.exr", 32, 16, structuredTexel);
  auto scene = sceneWith(envmapXml(map, 0.5f));
  const Emitter& env = onlyEmitter(*scene);
  expectRaysCrossTheBoundingSphere(env);
  // Ray directions (reversed: toward the emitter) follow pdfDirection.
  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) {
    Ray ray;
    env.sampleRay({0.5f, 0.5f}, u, ray);
    return -ray.d;
  };
  std::function<double(const Vec3f&)> pdf = [&](const Vec3f& d) {
    DirectionSample ds;
    ds.d = d;
    ds.dist = Infinity;
    return env.pdfDirection({0, 0, 0}, ds);
  };
  ChiSquareResult r = testSampler<Vec3f>(sphericalDomain(32, 64), sample, pdf, 500000, 16);
  EXPECT_GT(r.pValue, Significance) << r.message;
  // Power = pi R^2 times the radiance integrated over directions, which is
  // the mean of the ray weights (an independent Monte Carlo estimate).
  MeanAccumulator weights;
  PCG32 rng(8, 1);
  for (int i = 0; i < 200000; ++i) {
    Ray ray;
    weights.add(env.sampleRay({rng.nextFloat(), rng.nextFloat()}, {rng.nextFloat(), rng.nextFloat()}, ray));
  }
  Estimate e = weights.estimate();
  Color3f power = env.power();
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], power[c], 5.0f * e.standardError[c] + 1e-4f * power[c]);
}

TEST_F(EnvironmentMapTest, PathTracedPlaneMatchesTheIntegralOfTheMap) {
  // A diffuse plane facing +z under a structured map reflects
  //   L = rho / pi * int_{z > 0} L_env(w) cos(theta) dw,
  // computed here by quadrature of evalEnvironment; the path integrator must
  // agree, which needs consistent emitter-sampling densities for MIS.
  const Color3f rho(0.3f, 0.6f, 0.9f);
  auto map = writeMap(dir_, "structured.exr", 32, 16, structuredTexel);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"/>
  <shape type="rectangle">
    <transform name="to_world"><scale value="10"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(rho), R"("/></bsdf>
  </shape>
  )", envmapXml(map, 1.0f, R"(<transform name="to_world"><rotate x="1" angle="-60"/></transform>)"), R"(
</scene>)"));
  const Emitter& env = *scene->environmentEmitters().at(0);
  Color3f expected;
  for (int c = 0; c < 3; ++c) {
    std::function<double(const Vec3f&)> integrand = [&](const Vec3f& w) {
      return w.z > 0.0f ? env.evalEnvironment(Ray({0, 0, 0}, w))[c] * w.z : 0.0;
    };
    std::vector<double> cells = integrateCells(sphericalDomain(256, 512), integrand, 2);
    expected[c] = float(rho[c] * InvPi * std::accumulate(cells.begin(), cells.end(), 0.0));
  }
  Estimate e = estimateLi(*scene, 20000, [](PCG32&) { return Ray({0.2f, 0.1f, 3.0f}, normalize(Vec3f(0.1f, -0.2f, -1.0f))); });
  for (int c = 0; c < 3; ++c)  // the quadrature is good to about 1e-3
    EXPECT_NEAR(e.mean[c], expected[c], 5.0f * e.standardError[c] + 2e-3f * expected[c]) << "channel " << c;
}

TEST_F(EnvironmentMapTest, LatitudeLongitudeConventionIsMitsubas) {
  // 4 x 2 texels, each a different colour. Texel (x, y) is centred at
  // theta = (y + 1/2) pi / 2 from +y and phi = (x + 1/2) pi / 2, measured from -z toward +x.
  auto texelColour = [](int x, int y) { return Color3f(float(x), float(y), 1.0f); };
  auto map = writeMap(dir_, "quadrants.exr", 4, 2, texelColour);
  auto scene = sceneWith(envmapXml(map));
  const Emitter& env = onlyEmitter(*scene);
  const float s = std::sqrt(0.5f);
  // Upper half (y = 0): directions with +y; e.g. texel 1 (phi = 3pi/4) looks toward +x +z.
  expectColorNear(env.evalEnvironment(Ray({0, 0, 0}, Vec3f(0.5f, s, 0.5f))), texelColour(1, 0), 1e-4f);
  expectColorNear(env.evalEnvironment(Ray({0, 0, 0}, Vec3f(0.5f, s, -0.5f))), texelColour(0, 0), 1e-4f);
  expectColorNear(env.evalEnvironment(Ray({0, 0, 0}, Vec3f(-0.5f, -s, 0.5f))), texelColour(2, 1), 1e-4f);
  expectColorNear(env.evalEnvironment(Ray({0, 0, 0}, Vec3f(-0.5f, -s, -0.5f))), texelColour(3, 1), 1e-4f);
  // to_world rotates the map: 90 degrees about +y takes +z to +x.
  auto rotated = sceneWith(envmapXml(map, 1.0f, R"(<transform name="to_world"><rotate y="1" angle="90"/></transform>)"));
  expectColorNear(onlyEmitter(*rotated).evalEnvironment(Ray({0, 0, 0}, Vec3f(0.5f, s, -0.5f))), texelColour(1, 0), 1e-4f);
}

TEST_F(EnvironmentMapTest, BadFilesAreErrorsNamingTheFile) {
  auto negative = writeMap(dir_, "negative.exr", 4, 2, [](int x, int) { return Color3f(x == 1 ? -1.0f : 1.0f); });
  std::string message;
  try {
    sceneWith(envmapXml(negative));
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("negative.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("negative or non-finite"), std::string::npos) << message;
}

TEST(DirectionalEmitter, DiffusePlaneReflectsRhoOverPiTimesIrradianceCosine) {
  // L = rho / pi * E cos(theta) for a light arriving at theta from the normal;
  // the light is found only by next-event estimation, so Li has no variance.
  const Color3f rho(0.2f, 0.5f, 0.8f), E(2.0f, 1.0f, 3.0f);
  for (float thetaDeg : {0.0f, 30.0f, 75.0f}) {
    SCOPED_TRACE(str("theta ", thetaDeg));
    float theta = degToRad(thetaDeg);
    Vec3f travel(std::sin(theta), 0.0f, -std::cos(theta));
    auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"/>
  <shape type="rectangle">
    <transform name="to_world"><scale value="10"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(rho), R"("/></bsdf>
  </shape>
  <emitter type="directional">
    <vector name="direction" x=")", travel.x, R"(" y=")", travel.y, R"(" z=")", travel.z, R"("/>
    <rgb name="irradiance" value=")", rgb(E), R"("/>
  </emitter>
</scene>)"));
    Estimate e = estimateLi(*scene, 8, [](PCG32&) { return Ray({0.3f, 0.2f, 4.0f}, normalize(Vec3f(-0.1f, 0.3f, -1.0f))); });
    expectWithinErrorBars(e, rho * E * (InvPi * std::cos(theta)));
  }
}

TEST(DirectionalEmitter, PowerAndRaysCoverTheSceneSphere) {
  const Color3f E(1.0f, 2.0f, 3.0f);
  auto scene = sceneWith(str(R"(<emitter type="directional"><rgb name="irradiance" value=")", rgb(E),
                             R"("/><transform name="to_world"><rotate x="1" angle="30"/></transform></emitter>)"));
  const Emitter& light = onlyEmitter(*scene);
  EXPECT_TRUE(light.isDelta());
  expectColorNear(light.power(), E * (Pi * SphereRadius * SphereRadius), 1e-5f);
  expectRaysCrossTheBoundingSphere(light);
  Vec3f travel = normalize(Transform::rotate({1, 0, 0}, 30.0f).vector({0, 0, 1}));
  Ray ray;
  light.sampleRay({0.2f, 0.9f}, {0.5f, 0.5f}, ray);
  EXPECT_NEAR(dot(ray.d, travel), 1.0f, 1e-5f);
  DirectionSample ds;
  EXPECT_EQ(light.sampleDirection({0, 0, 0}, {0.5f, 0.5f}, ds), E);
  EXPECT_NEAR(dot(ds.d, -travel), 1.0f, 1e-5f);
  EXPECT_TRUE(ds.delta);
  EXPECT_EQ(ds.dist, Infinity);
}
