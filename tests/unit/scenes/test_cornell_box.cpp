// The shipped Cornell box scene (what `make render` renders) loads strictly
// and renders a plausible image: lit, finite, red on the left, green on the right.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/image/image_io.h>
#include <femto/render/integrator.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

using namespace femto;

TEST(CornellBoxScene, LoadsStrictlyAndRendersRedLeftGreenRight) {
  LoadOptions options;
  options.strict = true;
  options.resolution = Point2i(32, 32);
  options.sampleCount = 8;
  auto scene = loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box/scene.xml", options);
  EXPECT_EQ(scene->emitters().size(), 1u);

  std::filesystem::path dir = std::filesystem::temp_directory_path() / "femto-cornell-box-test";
  std::filesystem::create_directories(dir);
  RenderOptions render;
  render.output = dir / "cbox.exr";
  render.progress = false;
  RenderStats stats = scene->integrator().render(*scene, render);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  Bitmap image = readImage(render.output);
  ASSERT_EQ(image.width, 32);
  ASSERT_GE(image.channels, 3);

  // Average colour of a column band (x in [x0, x1)) over the middle rows.
  auto band = [&](int x0, int x1) {
    double rgb[3] = {0, 0, 0};
    for (int y = 12; y < 20; ++y)
      for (int x = x0; x < x1; ++x)
        for (int c = 0; c < 3; ++c) rgb[c] += image.pixel(x, y)[c];
    return Color3f(float(rgb[0]), float(rgb[1]), float(rgb[2]));
  };
  Color3f left = band(0, 3), right = band(29, 32), centre = band(14, 18);
  EXPECT_GT(left.r, 2.0f * left.g) << "left wall " << left;
  EXPECT_GT(right.g, 2.0f * right.r) << "right wall " << right;
  EXPECT_GT(centre.average(), 0.0f);
  std::filesystem::remove_all(dir);
}
