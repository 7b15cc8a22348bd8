// Render loop: bitwise determinism across thread counts, invalid-sample
// accounting, crop windows and cancellation.
#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <atomic>
#include <limits>

#include <femto/image/image_io.h>
#include <femto/render/mesh.h>
#include <femto/loop/render_loop.h>
#include <femto/render/scene.h>

#include "render_test_util.h"

namespace femto {
namespace {

/// Returns sampler values (and the hit distance), so any change in the
/// per-pixel sample streams or in the summation order changes the image.
class SamplerValuesIntegrator final : public SamplingIntegrator {
 public:
  Color3f Li(const Ray& ray, const Scene& scene, Sampler& sampler) const override {
    float a = sampler.next1D();
    SurfaceInteraction si;
    if (!scene.rayIntersect(ray, si)) return Color3f(a, 0, 0);
    return Color3f(a, 0.1f * si.t, sampler.next1D());
  }
};

std::shared_ptr<Scene> makeScene(int width, int height, int spp, const Properties* extraFilm = nullptr) {
  Properties film = extraFilm ? *extraFilm : Properties("hdrfilm");
  film.setPluginName("hdrfilm");
  film.setInt("width", width);
  film.setInt("height", height);
  Properties sampler("independent");
  sampler.setInt("sample_count", spp);
  Properties sensor("perspective");
  sensor.setFloat("fov", 60);
  sensor.setObject("film", test::makePlugin<Object>(ObjectKind::Film, film));
  sensor.setObject("sampler", test::makePlugin<Object>(ObjectKind::Sampler, sampler));

  auto mesh = std::make_shared<TriangleMesh>(Properties("test_mesh"));
  mesh->setGeometry({{-1, -1, 3}, {1, -1, 4}, {0, 1, 3.5f}}, {0, 1, 2}, {}, {}, Transform(), false, false);
  Properties scene("scene");
  scene.setObject("sensor", test::makePlugin<Object>(ObjectKind::Sensor, sensor));
  scene.setObject("integrator", std::make_shared<SamplerValuesIntegrator>());
  scene.setObject("mesh", mesh);
  return std::make_shared<Scene>(scene);
}

std::vector<float> renderImage(const Scene& scene, uint64_t seed, const std::filesystem::path& out, int threads = 0) {
  RenderOptions options;
  options.seed = seed;
  options.output = out;
  options.progress = false;
  options.threads = threads;
  RenderStats stats = scene.integrator().render(scene, options);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  return readImage(out).data;
}

TEST(RenderLoop, ImageIsBitwiseIdenticalForAnyThreadCount) {
  auto dir = test::scratchDir("determinism");
  auto scene = makeScene(70, 45, 3);  // partial tiles at the right and bottom edges
  std::vector<float> one, two, arena;
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    one = renderImage(*scene, 7, dir / "one.exr");
  }
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
    two = renderImage(*scene, 7, dir / "two.exr");
  }
  arena = renderImage(*scene, 7, dir / "arena.exr", 2);
  ASSERT_EQ(one.size(), size_t(70 * 45 * 3));
  EXPECT_TRUE(one == two);  // bitwise, not approximately
  EXPECT_TRUE(one == arena);
  EXPECT_TRUE(std::filesystem::exists(dir / "one.png"));  // hdrfilm writes a preview beside the EXR
  // The seed matters.
  EXPECT_FALSE(one == renderImage(*scene, 8, dir / "other.exr"));
  std::filesystem::remove_all(dir);
}

TEST(RenderLoop, CountsAndDropsInvalidSamples) {
  auto scene = makeScene(40, 8, 2);
  const Film& film = scene->sensor().film();
  ImageBlock result(film.cropOffset(), film.cropSize(), film.filter());
  RenderOptions options;
  options.progress = false;
  RenderStats stats = renderTiles(
      *scene, options,
      [](const Point2f& pos, Sampler&) {
        return pos.x < 10.0f ? Color3f(std::numeric_limits<float>::quiet_NaN()) : Color3f(1.0f);
      },
      result);
  EXPECT_EQ(stats.samples, 40u * 8u * 2u);
  EXPECT_EQ(stats.invalidSamples, 10u * 8u * 2u);
  EXPECT_TRUE(result.value({30, 4}) == Color3f(1.0f));
  EXPECT_TRUE(result.value({30, 4}).isValid());
}

TEST(RenderLoop, SamplesOnlyTheCropWindowInFullFilmCoordinates) {
  Properties film("hdrfilm");
  film.setInt("crop_offset_x", 20);
  film.setInt("crop_offset_y", 5);
  film.setInt("crop_width", 33);
  film.setInt("crop_height", 7);
  auto scene = makeScene(64, 32, 1, &film);
  const Film& f = scene->sensor().film();
  ASSERT_EQ(f.cropSize(), Point2i(33, 7));
  ImageBlock result(f.cropOffset(), f.cropSize(), f.filter());
  RenderOptions options;
  options.progress = false;
  std::atomic<int> outside{0};
  RenderStats stats = renderTiles(
      *scene, options,
      [&](const Point2f& pos, Sampler&) {
        if (pos.x < 20 || pos.x >= 53 || pos.y < 5 || pos.y >= 12) ++outside;
        return Color3f(1.0f);
      },
      result);
  EXPECT_EQ(outside.load(), 0);
  EXPECT_EQ(stats.samples, 33u * 7u);
  // The film writes only the crop window.
  auto dir = test::scratchDir("crop");
  f.develop(result, dir / "crop.exr");
  Bitmap image = readImage(dir / "crop.exr");
  EXPECT_EQ(image.width, 33);
  EXPECT_EQ(image.height, 7);
  EXPECT_FLOAT_EQ(image.pixel(0, 0)[1], 1.0f);
  std::filesystem::remove_all(dir);
}

TEST(RenderLoop, CancelledRenderStillWritesAValidImage) {
  auto dir = test::scratchDir("cancel");
  auto scene = makeScene(40, 40, 1);
  std::atomic<bool> cancel{true};
  RenderOptions options;
  options.progress = false;
  options.cancel = &cancel;
  options.output = dir / "partial.exr";
  RenderStats stats = scene->integrator().render(*scene, options);
  EXPECT_FALSE(stats.completed);
  Bitmap image = readImage(dir / "partial.exr");
  EXPECT_EQ(image.width, 40);
  for (float v : image.data) EXPECT_EQ(v, 0.0f);
  std::filesystem::remove_all(dir);
}

TEST(Film, RejectsCropWindowsOutsideTheFilm) {
  Properties film("hdrfilm");
  film.setInt("width", 10);
  film.setInt("crop_offset_x", 4);
  film.setInt("crop_width", 7, SourceLocation{"scene.xml", 12});
  try {
    test::makePlugin<Film>(ObjectKind::Film, film);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("scene.xml:12"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("crop_width"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace femto
