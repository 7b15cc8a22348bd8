// The projector emitter: the image it casts on a plane facing it is the
// irradiance texture (inverse-square and cosine laws applied), its frustum
// takes the image's aspect ratio, emitted rays are uniform over the image
// plane with weights that carry the power, and the power equals a numerical
// integral of the intensity over the sphere.
#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>

#include <femto/image/image_io.h>
#include <femto/math/pcg32.h>
#include <femto/render/emitter.h>
#include <femto/render/texture.h>

#include "chi2.h"
#include "expect_color.h"
#include "plugin_util.h"
#include "render_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int Width = 4, Height = 2;

/// Texel (x, y) = (1 + x, 1 + y, 1 + x + 4 y): all different, all positive.
Color3f texel(int x, int y) { return Color3f(1.0f + x, 1.0f + y, 1.0f + x + 4.0f * y); }

class ProjectorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir("projector");
    Bitmap image(Width, Height, 3);
    for (int y = 0; y < Height; ++y)
      for (int x = 0; x < Width; ++x)
        for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = texel(x, y)[c];
    writeEXR(dir_ / "slide.exr", image);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  /// A projector at the origin looking down +z (identity to_world), horizontal fov 90 degrees.
  std::shared_ptr<Emitter> makeProjector(float scale = 2.0f) const {
    Properties texture("bitmap");
    texture.setString("filename", (dir_ / "slide.exr").string());
    texture.setString("filter_type", "nearest");
    Properties props("projector");
    props.setObject("irradiance", makePlugin<Texture>(ObjectKind::Texture, texture));
    props.setFloat("scale", scale);
    props.setFloat("fov", 90.0f);
    return makePlugin<Emitter>(ObjectKind::Emitter, props);
  }

  std::filesystem::path dir_;
};

/// Irradiance the light casts on the plane z = depth at (x, y), facing it.
Color3f irradianceOnPlane(const Emitter& light, float x, float y, float depth) {
  DirectionSample ds;
  Color3f value = light.sampleDirection(Point3f(x, y, depth), {0.5f, 0.5f}, ds);
  EXPECT_TRUE(ds.delta);
  return value * (-ds.d.z);  // cosine of incidence on the plane (normal -z)
}

}  // namespace

TEST_F(ProjectorTest, CastsItsImageAsIrradianceOnAFacingPlane) {
  auto light = makeProjector(2.0f);
  // fov 90 along x: tan = 1, so the plane z = depth spans x in [-depth, depth]
  // and, with the 4 x 2 image, y in [-depth/2, depth/2]. The image's left
  // column is at +x and its top row at +y (as the camera sees its film).
  for (float depth : {1.0f, 3.0f})
    for (int y = 0; y < Height; ++y)
      for (int x = 0; x < Width; ++x) {
        float u = (x + 0.5f) / Width, v = (y + 0.5f) / Height;
        float px = (1.0f - 2.0f * u) * depth, py = (1.0f - 2.0f * v) * 0.5f * depth;
        SCOPED_TRACE(str("depth ", depth, " texel ", x, ",", y));
        expectColorNear(irradianceOnPlane(*light, px, py, depth), texel(x, y) * (2.0f / (depth * depth)), 1e-4f);
      }
}

TEST_F(ProjectorTest, TheFrustumTakesTheImagesAspectRatio) {
  auto light = makeProjector();
  EXPECT_FALSE(irradianceOnPlane(*light, 0.0f, 0.45f, 1.0f).isBlack());
  EXPECT_TRUE(irradianceOnPlane(*light, 0.0f, 0.55f, 1.0f).isBlack());  // tan(fov_y / 2) = 0.5
  EXPECT_FALSE(irradianceOnPlane(*light, -0.95f, 0.0f, 1.0f).isBlack());
  EXPECT_TRUE(irradianceOnPlane(*light, -1.05f, 0.0f, 1.0f).isBlack());
  EXPECT_TRUE(irradianceOnPlane(*light, 0.0f, 0.0f, -1.0f).isBlack());  // behind it
}

TEST_F(ProjectorTest, PowerIsTheIntensityIntegratedOverTheSphere) {
  auto light = makeProjector(2.0f);
  // Plane area 4 tan_x tan_y = 2, mean texel (2.5, 1.5, 4.5): power = 2 * 2 * mean.
  expectColorNear(light->power(), Color3f(2.5f, 1.5f, 4.5f) * 4.0f, 1e-4f);
  GridDomain<Vec3f> domain = sphericalDomain(200, 200);
  std::function<double(const Vec3f&)> blue = [&](const Vec3f& d) {
    DirectionSample ds;
    return double(light->sampleDirection(Point3f(d.x, d.y, d.z), {0.5f, 0.5f}, ds)[2]);  // unit distance
  };
  std::vector<double> cells = integrateCells(domain, blue, 8);
  double integral = std::accumulate(cells.begin(), cells.end(), 0.0);
  EXPECT_NEAR(light->power()[2], integral, 5e-3 * integral);
}

TEST_F(ProjectorTest, EmittedRaysAreUniformOverTheImagePlaneAndCarryThePower) {
  auto light = makeProjector(2.0f);
  PCG32 rng(7, 11);
  const int n = 20000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    Point2f u(rng.nextFloat(), rng.nextFloat());
    Ray ray;
    Color3f weight = light->sampleRay({0.5f, 0.5f}, u, ray);
    // The direction hits the image plane at the sampled point ...
    Vec3f onPlane = ray.d / ray.d.z;
    EXPECT_NEAR(onPlane.x, 1.0f - 2.0f * u.x, 1e-4f);
    EXPECT_NEAR(onPlane.y, 0.5f * (1.0f - 2.0f * u.y), 1e-4f);
    // ... and weight * (direction density 1 / (area z^3): d(omega) = z^3 dA) is the intensity there.
    DirectionSample ds;
    Color3f intensity = light->sampleDirection(Point3f(ray.d.x, ray.d.y, ray.d.z), {0.5f, 0.5f}, ds);
    float pdf = 1.0f / (2.0f * ray.d.z * ray.d.z * ray.d.z);
    if (u.x > 0.001f && u.x < 0.999f && u.y > 0.001f && u.y < 0.999f)  // texel edges are exact only inside
      expectColorNear(weight * pdf, intensity, 2e-3f * intensity[2]);
    sum += weight[2];
    sum2 += double(weight[2]) * weight[2];
  }
  double mean = sum / n, stderror = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, light->power()[2], 5.0 * stderror + 1e-9);
}

TEST_F(ProjectorTest, BadParametersAreErrors) {
  Properties fov("projector");
  fov.setFloat("fov", 180.0f);
  EXPECT_NE(errorMessageOf([&] { makePlugin<Emitter>(ObjectKind::Emitter, fov); }).find("fov"), std::string::npos);
  Properties scale("projector");
  scale.setFloat("scale", -1.0f);
  EXPECT_NE(errorMessageOf([&] { makePlugin<Emitter>(ObjectKind::Emitter, scale); }).find("scale"), std::string::npos);
  // Without an image the frustum is square (procedural textures have no aspect ratio).
  Properties plain("projector");
  plain.setFloat("fov", 90.0f);
  auto light = makePlugin<Emitter>(ObjectKind::Emitter, plain);
  EXPECT_FALSE(irradianceOnPlane(*light, 0.0f, 0.95f, 1.0f).isBlack());
}
