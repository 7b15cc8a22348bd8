// Accuracy of the `path` integrator against closed forms. Tolerances come
// from the estimator's own standard error (5 sigma), measured from the
// samples, plus a float round-off allowance for zero-variance estimators.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/image/image_io.h>
#include <femto/math/pcg32.h>
#include <femto/math/warp.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "li_estimate.h"

using namespace femto;
using namespace femto::test;

namespace {

/// White furnace: a closed unit sphere whose inside is diffuse with
/// reflectance rho and emits Le everywhere. Every path vertex sees emission
/// Le, and each bounce multiplies by rho, so a path of exactly j segments
/// carries Le rho^(j-1). With max_depth = k counting segments (Mitsuba's
/// convention: 1 = emitters seen directly, 2 = plus direct lighting)
///   L = Le (1 + rho + ... + rho^(k-1)) = Le (1 - rho^k) / (1 - rho),
/// and Le / (1 - rho) without a limit.
std::shared_ptr<Scene> furnaceScene(const Color3f& rho, const Color3f& Le, const std::string& integratorParams,
                                    const std::string& filmParams = "", const std::string& sampleCount = "1") {
  return loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path">)", integratorParams, R"(</integrator>
  <sensor type="perspective">
    <film type="hdrfilm">)", filmParams, R"(</film>
    <sampler type="independent"><integer name="sample_count" value=")", sampleCount, R"("/></sampler>
  </sensor>
  <shape type="sphere">
    <boolean name="flip_normals" value="true"/>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(rho), R"("/></bsdf>
    <emitter type="area"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
  </shape>
</scene>)"));
}

Color3f furnaceRadiance(const Color3f& rho, const Color3f& Le, int maxDepth) {
  Color3f L;
  for (int c = 0; c < 3; ++c)
    L[c] = maxDepth < 0 ? Le[c] / (1.0f - rho[c]) : Le[c] * (1.0f - std::pow(rho[c], float(maxDepth))) / (1.0f - rho[c]);
  return L;
}

const Color3f Rho(0.3f, 0.5f, 0.8f);
const Color3f Le(1.0f, 0.5f, 2.0f);

}  // namespace

TEST(PathFurnace, DepthOneSeesOnlyEmission) {
  auto scene = furnaceScene(Rho, Le, R"(<integer name="max_depth" value="1"/>)");
  Estimate e = estimateLi(*scene, 2000, randomInteriorRay);
  expectWithinErrorBars(e, furnaceRadiance(Rho, Le, 1));
  EXPECT_EQ(e.standardError, Color3f(0.0f));
}

TEST(PathFurnace, BoundedDepthsMatchTheGeometricSeries) {
  for (int k : {2, 3, 6}) {
    SCOPED_TRACE(str("max_depth = ", k));
    auto scene = furnaceScene(Rho, Le, str(R"(<integer name="max_depth" value=")", k, R"("/>)"));
    expectWithinErrorBars(estimateLi(*scene, 20000, randomInteriorRay), furnaceRadiance(Rho, Le, k));
  }
}

TEST(PathFurnace, UnboundedDepthConvergesToLeOverOneMinusRho) {
  // Russian roulette from the first bounce and from the default depth 5 must both stay unbiased.
  for (const char* rr : {"1", "5"}) {
    SCOPED_TRACE(str("rr_depth = ", rr));
    auto scene = furnaceScene(Rho, Le, str(R"(<integer name="rr_depth" value=")", rr, R"("/>)"));
    expectWithinErrorBars(estimateLi(*scene, 40000, randomInteriorRay), furnaceRadiance(Rho, Le, -1));
  }
}

TEST(PathFurnace, HideEmittersRemovesOnlyDirectlyVisibleEmission) {
  auto scene = furnaceScene(Rho, Le, R"(<integer name="max_depth" value="2"/><boolean name="hide_emitters" value="true"/>)");
  expectWithinErrorBars(estimateLi(*scene, 20000, randomInteriorRay), Rho * Le);
}

TEST(PathFurnace, RenderedImageMatchesTheClosedForm) {
  // The whole pipeline: camera, render loop, box-filtered film, EXR output.
  // With a box filter pixels are independent estimates, so the spread of the
  // pixel values gives the standard error of the image mean.
  const int spp = 16, size = 16;
  auto scene = furnaceScene(Rho, Le, "",
                            str(R"(<integer name="width" value=")", size, R"("/><integer name="height" value=")", size,
                                R"("/><rfilter type="box"/>)"),
                            std::to_string(spp));
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "femto-path-furnace";
  std::filesystem::create_directories(dir);
  RenderOptions options;
  options.output = dir / "furnace.exr";
  options.progress = false;
  options.threads = 2;
  RenderStats stats = scene->integrator().render(*scene, options);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  Bitmap image = readImage(options.output);
  ASSERT_EQ(image.width, size);
  ASSERT_EQ(image.height, size);
  ASSERT_GE(image.channels, 3);
  MeanAccumulator pixels;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) pixels.add(Color3f(image.pixel(x, y)[0], image.pixel(x, y)[1], image.pixel(x, y)[2]));
  Estimate e = pixels.estimate();
  expectWithinErrorBars(e, furnaceRadiance(Rho, Le, -1));
  std::filesystem::remove_all(dir);
}

namespace {

/// A point light of intensity I at height h over a large diffuse plane z = 0.
/// Irradiance at x is E = I cos(theta) / d^2 with d = |light - x| and
/// cos(theta) = h / d; the plane reflects L = rho / pi * E toward any viewer
/// above it. Next-event estimation finds a point light exactly, and the
/// continuation escapes, so Li has no variance.
const Color3f PlaneRho(0.2f, 0.5f, 0.8f);
const Color3f Intensity(1.0f, 2.0f, 3.0f);
const Point3f LightPos(0.5f, -0.3f, 2.0f);

std::shared_ptr<Scene> pointOverPlaneScene(int maxDepth) {
  return loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value=")", maxDepth, R"("/></integrator>
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(PlaneRho), R"("/></bsdf>
  </shape>
  <emitter type="point">
    <point name="position" x=")", LightPos.x, R"(" y=")", LightPos.y, R"(" z=")", LightPos.z, R"("/>
    <rgb name="intensity" value=")", rgb(Intensity), R"("/>
  </emitter>
</scene>)"));
}

}  // namespace

TEST(PathPointLight, DiffusePlaneRadianceMatchesTheInverseSquareLaw) {
  auto scene = pointOverPlaneScene(-1);
  const Point3f eye(0.2f, 0.1f, 5.0f);
  for (Point3f target : {Point3f(0, 0, 0), Point3f(0.5f, -0.3f, 0), Point3f(3, 2, 0), Point3f(-6, 1, 0)}) {
    SCOPED_TRACE(str("target ", target));
    Estimate e = estimateLi(*scene, 4, [&](PCG32&) { return Ray(eye, normalize(target - eye)); });
    float d = distance(LightPos, target);
    float irradianceScale = (LightPos.z / d) / (d * d);
    expectWithinErrorBars(e, PlaneRho * Intensity * (InvPi * irradianceScale));
  }
}

TEST(PathPointLight, TheBackOfTheOneSidedPlaneIsBlackAndDepthOneSeesNoLight) {
  auto scene = pointOverPlaneScene(-1);
  Estimate below = estimateLi(*scene, 4, [](PCG32&) { return Ray({0, 0, -3}, {0, 0, 1}); });
  EXPECT_EQ(below.mean, Color3f(0.0f));
  auto direct = pointOverPlaneScene(1);
  Estimate above = estimateLi(*direct, 4, [](PCG32&) { return Ray({0, 0, 3}, {0, 0, -1}); });
  EXPECT_EQ(above.mean, Color3f(0.0f));
}

TEST(PathSphereLight, DirectLightingMatchesTheSphereFormFactor) {
  // max_depth 2: direct lighting only.
  expectSphereLightFormFactor(R"(<integrator type="path"><integer name="max_depth" value="2"/></integrator>)",
                              PlaneRho, {Point3f(0, 0, 0), Point3f(1.5f, 0, 0), Point3f(0.5f, -1.0f, 0)});
}
