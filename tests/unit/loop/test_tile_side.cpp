// The tile side shrinks so that the tiles in flight stay under
// TileMemoryBound, and a transient render's values do not depend on it.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <femto/base/error.h>
#include <femto/film/transient_tile.h>
#include <femto/loop/render_loop.h>
#include <femto/render/scene.h>

#include "media_test_util.h"
#include "render_test_util.h"

namespace femto {
namespace {

TEST(TileSide, StaysAtTheDefaultWhenTilesAreSmall) {
  EXPECT_EQ(tileSideWithin(0.0, 4), RenderTileSize);
  EXPECT_EQ(tileSideWithin(TransientTile::bytesPerPixel(512), 4), RenderTileSize);
}

TEST(TileSide, ShrinksToTheLargestSideUnderTheBound) {
  for (int bins : {1 << 16, 1 << 18, 1 << 20, 1 << 22})
    for (size_t inFlight : {size_t(2), size_t(4), size_t(128)}) {
      const double pixel = TransientTile::bytesPerPixel(bins);
      int side = 0;
      try {
        side = tileSideWithin(pixel, inFlight);
      } catch (const Error&) {
        EXPECT_GT(pixel * double(inFlight), TileMemoryBound) << "refused although one-pixel tiles fit";
        continue;
      }
      SCOPED_TRACE(testing::Message() << bins << " bins, " << inFlight << " tiles in flight: side " << side);
      EXPECT_LE(double(side) * side * pixel * double(inFlight), TileMemoryBound);
      if (side < RenderTileSize) EXPECT_GT(double(side + 1) * (side + 1) * pixel * double(inFlight), TileMemoryBound);
    }
}

TEST(TileSide, RefusesNamingTheSizesWhenOnePixelIsTooLarge) {
  try {
    tileSideWithin(TransientTile::bytesPerPixel(1 << 26), 4);
    FAIL() << "2^26 bins x 4 tiles in flight exceed the bound and were accepted";
  } catch (const Error& e) {
    std::string message = e.what();
    EXPECT_NE(message.find("GiB"), std::string::npos) << message;
    EXPECT_NE(message.find("fewer time bins"), std::string::npos) << message;
  }
}

std::string steadyImageBytes(int threads, const std::string& name) {
  // 2^18 bins: one 8x8 tile with 1 thread (2 in flight), 6x6 tiles with 2.
  auto scene = test::loadSceneStrict(R"(<scene version="3.0.0">
  <integrator type="transient_path"/>
  <sensor type="perspective">
    <transform name="to_world"><lookat origin="0, 0, 2" target="0, 0, 0" up="0, 1, 0"/></transform>
    <film type="transient"><integer name="width" value="8"/><integer name="height" value="8"/>
      <integer name="temporal_bins" value="262144"/><float name="bin_width_opl" value="0.0001"/>
      <boolean name="write_volume" value="false"/><boolean name="write_frames" value="false"/></film>
    <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
  </sensor>
  <shape type="rectangle"><bsdf type="diffuse"/></shape>
  <emitter type="point"><point name="position" x="0" y="0" z="1"/><rgb name="intensity" value="1"/></emitter>
</scene>)");
  RenderOptions options;
  options.threads = threads;
  options.progress = false;
  options.output = test::scratchDir(name) / "out.exr";
  scene->integrator().render(*scene, options);
  std::ifstream in(options.output, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(TileSide, TransientValuesDoNotDependOnTheTileSide) {
  ASSERT_NE(tileSideWithin(TransientTile::bytesPerPixel(1 << 18), 2),
            tileSideWithin(TransientTile::bytesPerPixel(1 << 18), 4));
  std::string one = steadyImageBytes(1, "tile-side-1"), two = steadyImageBytes(2, "tile-side-2");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace femto
