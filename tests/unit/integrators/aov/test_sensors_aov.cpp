// Orthographic camera, radiance and irradiance meters, and the aov
// integrator's values on a known plane.
#include <gtest/gtest.h>

#include <map>

#include <femto/image/image_io.h>

#include "li_estimate.h"
#include "plugin_util.h"
#include "render_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

/// Render `scene` to a scratch EXR and read it back with its channel names.
Bitmap renderToImage(const Scene& scene, const std::string& name, std::vector<std::string>& channels) {
  auto dir = scratchDir(name);
  RenderOptions options;
  options.output = dir / "image.exr";
  options.progress = false;
  options.threads = 2;
  RenderStats stats = scene.integrator().render(scene, options);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  ImageFileInfo info;
  Bitmap image = readImage(options.output, info);
  channels = info.channelNames;
  std::filesystem::remove_all(dir);
  return image;
}

}  // namespace

TEST(Orthographic, RaysAreParallelAndScaledByToWorld) {
  // Camera at z = 5 looking down at the origin, view scaled by 2: the film
  // (4 x 2 pixels, aspect 2) spans x_cam in [-2, 2] and y_cam in [-1, 1].
  auto scene = loadStrict(R"(<scene version="3.0.0">
  <sensor type="orthographic">
    <float name="near_clip" value="1"/><float name="far_clip" value="8"/>
    <transform name="to_world"><scale value="2"/><lookat origin="0,0,5" target="0,0,0" up="0,1,0"/></transform>
    <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="2"/></film>
  </sensor>
</scene>)");
  const Sensor& sensor = scene->sensor();
  Ray ray;
  EXPECT_EQ(sensor.sampleRay({2.0f, 1.0f}, {0.5f, 0.5f}, ray), Color3f(1.0f));
  EXPECT_NEAR(ray.o.x, 0.0f, 1e-5f);
  EXPECT_NEAR(ray.o.y, 0.0f, 1e-5f);
  EXPECT_NEAR(ray.o.z, 5.0f, 1e-5f);
  EXPECT_NEAR(ray.d.z, -1.0f, 1e-6f);
  // to_world scales camera z by 2 as well: clip depths are camera-space.
  EXPECT_NEAR(ray.tmin, 2.0f, 1e-5f);
  EXPECT_NEAR(ray.tmax, 16.0f, 1e-4f);
  // Top-left film corner: camera (+2, +1), i.e. world (-2, +1) (lookat maps camera +x to world -x here).
  sensor.sampleRay({0.0f, 0.0f}, {0.5f, 0.5f}, ray);
  EXPECT_NEAR(ray.o.x, -2.0f, 1e-5f);
  EXPECT_NEAR(ray.o.y, 1.0f, 1e-5f);
  EXPECT_NEAR(ray.d.z, -1.0f, 1e-6f);
}

TEST(RadianceMeter, MeasuresOneRayOnASinglePixelFilm) {
  auto scene = loadStrict(R"(<scene version="3.0.0">
  <sensor type="radiancemeter">
    <point name="origin" x="1" y="2" z="3"/><vector name="direction" x="0" y="0" z="-2"/>
  </sensor>
</scene>)");
  EXPECT_EQ(scene->sensor().film().size(), Point2i(1, 1));
  Ray ray;
  scene->sensor().sampleRay({0.3f, 0.7f}, {0.1f, 0.9f}, ray);
  EXPECT_EQ(ray.o, Point3f(1, 2, 3));
  EXPECT_EQ(ray.d, Vec3f(0, 0, -1));
  std::string message = errorMessageOf([] {
    loadStrict(R"(<scene version="3.0.0"><sensor type="radiancemeter"><point name="origin" x="1" y="2" z="3"/></sensor></scene>)");
  });
  EXPECT_NE(message.find("give both \"origin\" and \"direction\""), std::string::npos) << message;
}

TEST(IrradianceMeter, MeasuresPiLeInsideAnEmittingSphere) {
  // A meter on a small rectangle inside a black sphere emitting Le toward its
  // inside: every direction of the hemisphere sees Le, so E = pi Le exactly.
  const Color3f Le(1.0f, 2.0f, 0.5f);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"/>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.2"/></transform>
    <sensor type="irradiancemeter"><sampler type="independent"><integer name="sample_count" value="64"/></sampler></sensor>
  </shape>
  <shape type="sphere">
    <float name="radius" value="3"/><boolean name="flip_normals" value="true"/>
    <bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf>
    <emitter type="area"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
  </shape>
</scene>)"));
  std::vector<std::string> channels;
  Bitmap image = renderToImage(*scene, "irradiancemeter", channels);
  ASSERT_EQ(image.width, 1);
  ASSERT_EQ(image.height, 1);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(image.pixel(0, 0)[c], Pi * Le[c], 1e-3f * Pi * Le[c]);
}

TEST(IrradianceMeter, RefusedAtTopLevel) {
  std::string message = errorMessageOf([] {
    loadStrict(R"(<scene version="3.0.0"><sensor type="irradiancemeter"/></scene>)");
  });
  EXPECT_NE(message.find("nest it inside a <shape>"), std::string::npos) << message;
}

namespace {

/// An orthographic camera 5 above the plane z = 0 (a 20 x 20 diffuse
/// rectangle, shape 0), looking straight down over x, y in [-1, 1].
std::shared_ptr<Scene> aovPlaneScene(const std::string& aovs, const std::string& inner = "") {
  return loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="aov"><string name="aovs" value=")", aovs, R"("/>)", inner, R"(</integrator>
  <sensor type="orthographic">
    <transform name="to_world"><lookat origin="0,0,5" target="0,0,0" up="0,1,0"/></transform>
    <sampler type="stratified"><integer name="sample_count" value="16"/></sampler>
    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/><rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale value="10"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.4, 0.6"/></bsdf>
  </shape>
  <emitter type="point"><point name="position" x="0" y="0" z="3"/><rgb name="intensity" value="1"/></emitter>
</scene>)"));
}

}  // namespace

TEST(AOVIntegrator, DepthNormalsPositionAlbedoAndIndexOnAPlane) {
  auto scene = aovPlaneScene("dd.y:depth,nn:sh_normal,gn:geo_normal,pp:position,aa:albedo,ix:shape_index");
  std::vector<std::string> names;
  Bitmap image = renderToImage(*scene, "aov", names);
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.channels, 14);
  std::map<std::string, int> at;
  for (size_t i = 0; i < names.size(); ++i) at[names[i]] = int(i);
  for (const char* n : {"dd.y.T", "nn.X", "nn.Y", "nn.Z", "gn.Z", "pp.X", "pp.Y", "pp.Z", "aa.R", "aa.G", "aa.B", "ix.T"})
    ASSERT_TRUE(at.count(n)) << "missing channel " << n;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const float* px = image.pixel(x, y);
      EXPECT_NEAR(px[at["dd.y.T"]], 5.0f, 1e-4f);
      EXPECT_NEAR(px[at["nn.Z"]], 1.0f, 1e-6f);
      EXPECT_NEAR(px[at["nn.X"]], 0.0f, 1e-6f);
      EXPECT_NEAR(px[at["gn.Z"]], 1.0f, 1e-6f);
      EXPECT_NEAR(px[at["pp.Z"]], 0.0f, 1e-5f);
      // Stratified samples average to the pixel centre up to a fraction of the
      // pixel width (0.25); camera +x is world -x under this lookat.
      EXPECT_NEAR(px[at["pp.X"]], -(1.0f - 2.0f * (x + 0.5f) / 8.0f), 0.25f * 0.25f);
      EXPECT_NEAR(px[at["pp.Y"]], 1.0f - 2.0f * (y + 0.5f) / 8.0f, 0.25f * 0.25f);
      EXPECT_NEAR(px[at["aa.R"]], 0.2f, 1e-5f);
      EXPECT_NEAR(px[at["aa.B"]], 0.6f, 1e-5f);
      EXPECT_EQ(px[at["ix.T"]], 0.0f);
    }
}

TEST(AOVIntegrator, NestedIntegratorGivesRGBFirst) {
  auto scene = aovPlaneScene("dd:depth", R"(<integrator type="direct"/>)");
  std::vector<std::string> names;
  Bitmap image = renderToImage(*scene, "aov-nested", names);
  ASSERT_EQ(image.channels, 4);
  std::map<std::string, int> at;
  for (size_t i = 0; i < names.size(); ++i) at[names[i]] = int(i);
  ASSERT_TRUE(at.count("R") && at.count("dd.T"));
  // Under the point light 3 above the centre: L = rho / pi * I cos / d^2 with d ~ 3.
  const float* centre = image.pixel(4, 4);
  EXPECT_NEAR(centre[at["R"]], 0.2f * InvPi / 9.0f, 0.2f * 0.2f * InvPi / 9.0f);
  EXPECT_NEAR(centre[at["dd.T"]], 5.0f, 1e-4f);
}

TEST(AOVIntegrator, BadListsAreNamed) {
  std::string message = errorMessageOf([] { aovPlaneScene("dd:depht"); });
  EXPECT_NE(message.find("unknown AOV type \"depht\""), std::string::npos) << message;
  message = errorMessageOf([] { aovPlaneScene("depth"); });
  EXPECT_NE(message.find("expected \"name:type\""), std::string::npos) << message;
}

TEST(MomentIntegrator, MeanAndSecondMomentPerNestedIntegrator) {
  // Inside a closed black sphere emitting Le, a path tracer of max_depth 1
  // sees exactly Le (second moment Le^2); `direct` with a grey BSDF in the
  // same furnace has noise, so its second moment exceeds the squared mean.
  const Color3f Le(1.0f, 2.0f, 0.5f);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="moment">
    <integrator type="path"><integer name="max_depth" value="1"/></integrator>
    <integrator type="direct" id="dl"/>
  </integrator>
  <sensor type="perspective">
    <float name="fov" value="60"/>
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
    <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/><rfilter type="box"/></film>
  </sensor>
  <shape type="sphere">
    <boolean name="flip_normals" value="true"/>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf>
    <emitter type="area"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
  </shape>
</scene>)"));
  std::vector<std::string> names;
  Bitmap image = renderToImage(*scene, "moment", names);
  ASSERT_EQ(image.channels, 12);
  std::map<std::string, int> at;
  for (size_t i = 0; i < names.size(); ++i) at[names[i]] = int(i);
  for (const char* n : {"integrator_0.R", "integrator_0.m2.B", "dl.G", "dl.m2.R"})
    ASSERT_TRUE(at.count(n)) << "missing channel " << n;
  const char* rgbNames[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c) {
    const float* px = image.pixel(1, 2);
    std::string ch = rgbNames[c];
    EXPECT_NEAR(px[at["integrator_0." + ch]], Le[c], 1e-4f * Le[c]);
    EXPECT_NEAR(px[at["integrator_0.m2." + ch]], Le[c] * Le[c], 1e-4f * Le[c] * Le[c]);
    float mean = px[at["dl." + ch]];
    EXPECT_GT(px[at["dl.m2." + ch]], mean * mean);
  }
}

TEST(AOVIntegrator, RefusesATimeLimitBeforeAnyWork) {
  // One pass of arbitrary channels: a time limit or a pass count cannot be honoured.
  auto scene = aovPlaneScene("dd.y:depth");
  RenderOptions options;
  options.progress = false;
  options.timeLimit = 5.0;
  std::string message = errorMessageOf([&] { scene->integrator().render(*scene, options); });
  EXPECT_NE(message.find("cannot render to a time limit (--time-limit, --passes)"), std::string::npos) << message;
}
