// The hook a distributed render goes through (tile_distribution.h), in one
// process: tiles rendered in another order and sent through pack/unpack into
// fresh accumulators must give the same bits as the ordinary render, for a
// steady film (filtered, overlapping blocks) and a transient one (volume,
// steady, before/after). tests/cli/mpi/ runs the same over MPI ranks.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include <femto/base/error.h>
#include <femto/film/transient_film.h>
#include <femto/film/transient_tile.h>
#include <femto/loop/tile_distribution.h>
#include <femto/render/image_block.h>

#include "transient_film_test_util.h"

namespace femto {
namespace {

/// What a distribution over processes does, here: tiles rendered last first,
/// each shipped as floats into a new accumulator, all folded in tile order.
class ReversedShippingDistribution final : public TileDistribution {
 public:
  RenderStats run(TileJob& job) override {
    size_t next = job.tiles.size();
    std::vector<std::unique_ptr<TileAccumulator>> received(job.tiles.size());
    RenderStats stats;
    auto claim = [&]() -> RenderTile* { return next == 0 ? nullptr : &job.tiles[--next]; };
    auto deliver = [&](RenderTile& tile) {
      stats.samples += tile.samples, stats.invalidSamples += tile.invalid;
      if (!tile.accumulator) {  // stored by the thread that rendered it (job.consumeWhereRendered)
        ++storedWhereRendered;
        return;
      }
      std::vector<float> sums;
      tile.accumulator->pack(sums);
      tile.accumulator.reset();
      received[tile.index] = job.makeTile(tile.offset, tile.size);
      received[tile.index]->unpack(sums.data(), sums.size());
      floatsShipped += sums.size();
    };
    renderClaimedTiles(job, claim, deliver);
    for (auto& tile : received)
      if (tile) job.consume(*tile);
    stats.completed = true;
    return stats;
  }
  size_t floatsShipped = 0, storedWhereRendered = 0;
};

/// Installs a distribution for one scope.
struct ScopedDistribution {
  explicit ScopedDistribution(TileDistribution& d) { setTileDistribution(&d); }
  ~ScopedDistribution() { setTileDistribution(nullptr); }
};

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

RenderStats render(const Scene& scene, const std::filesystem::path& out) {
  RenderOptions options;
  options.output = out;
  options.progress = false;
  options.threads = 2;
  options.seed = 5;
  return scene.integrator().render(scene, options);
}

std::shared_ptr<Scene> rampScene(const char* filmType, int width, int height, bool gaussian = false) {
  Properties film(filmType);
  film.setInt("width", width);
  film.setInt("height", height);
  if (std::string(filmType) == "transient") {
    film.setInt("temporal_bins", 24);
    film.setFloat("start_opl", 2.0);
    film.setFloat("bin_width_opl", 2.0);
    film.setString("time_filter", "tent");
    film.setBool("write_frames", false);
  }
  if (gaussian || std::string(filmType) != "transient") {
    // Wider than a pixel: neighbouring tiles' blocks overlap, so the merge
    // order shows in the bits.
    Properties gaussian("gaussian");
    film.setObject("rfilter", test::makeTestPlugin(ObjectKind::ReconstructionFilter, gaussian));
  }
  Properties ramp("test_transient_ramp");
  ramp.setFloat("jitter", 5.0);
  return test::makeRampScene(film, ramp, 3);
}

TEST(TileDistribution, SteadyImageShippedBetweenAccumulatorsIsBitwiseTheSame) {
  auto dir = test::scratchDir("distribution-steady");
  auto scene = rampScene("hdrfilm", 70, 45);  // partial tiles at the right and bottom
  RenderStats plain = render(*scene, dir / "plain.exr");
  ReversedShippingDistribution distribution;
  RenderStats shipped;
  {
    ScopedDistribution scope(distribution);
    shipped = render(*scene, dir / "shipped.exr");
  }
  EXPECT_GT(distribution.floatsShipped, 0u);
  EXPECT_EQ(shipped.samples, plain.samples);
  EXPECT_EQ(fileBytes(dir / "plain.exr"), fileBytes(dir / "shipped.exr"));
  std::filesystem::remove_all(dir);
}

/// A transient render through the reversed distribution has the bits of the plain one.
ReversedShippingDistribution expectTransientBitwiseTheSame(const Scene& scene, const char* name) {
  auto dir = test::scratchDir(name);
  render(scene, dir / "plain.exr");
  ReversedShippingDistribution distribution;
  {
    ScopedDistribution scope(distribution);
    render(scene, dir / "shipped.exr");
  }
  for (const char* file : {".npy", ".exr", "_before.exr", "_after.exr"})
    EXPECT_EQ(fileBytes(dir / (std::string("plain") + file)), fileBytes(dir / (std::string("shipped") + file))) << file;
  std::filesystem::remove_all(dir);
  return distribution;
}

TEST(TileDistribution, TransientVolumeShippedBetweenAccumulatorsIsBitwiseTheSame) {
  // A pixel filter wider than a pixel: tiles carry borders, shipped and merged in tile order.
  auto scene = rampScene("transient", 70, 40, /*gaussian=*/true);
  ReversedShippingDistribution distribution = expectTransientBitwiseTheSame(*scene, "distribution-transient");
  EXPECT_GT(distribution.floatsShipped, size_t(70 * 40) * (24 * 3 + 10));
  EXPECT_EQ(distribution.storedWhereRendered, 0u);
}

TEST(TileDistribution, TransientTilesStoredWhereRenderedInAnyOrderAreBitwiseTheSame) {
  // The box filter: each tile is stored alone, by the thread that rendered it, last tile first.
  auto scene = rampScene("transient", 70, 40);
  ReversedShippingDistribution distribution = expectTransientBitwiseTheSame(*scene, "distribution-stored");
  EXPECT_EQ(distribution.floatsShipped, 0u);
  EXPECT_EQ(distribution.storedWhereRendered, 6u);  // 70 x 40 in 32-pixel tiles
}

TEST(TileDistribution, SumsOfAnotherTileAreRefused) {
  auto scene = rampScene("transient", 40, 8);
  const TimeDeposit& deposit = static_cast<const TransientFilm&>(scene->sensor().film()).timeDeposit();
  auto* integrator = dynamic_cast<const TransientIntegrator*>(&scene->integrator());
  ASSERT_NE(integrator, nullptr);
  TransientRenderContext context{*scene, *integrator, deposit};
  TransientTile big({0, 0}, {32, 8}, context), small({32, 0}, {8, 8}, context);
  std::vector<float> sums;
  big.pack(sums);
  EXPECT_THROW(small.unpack(sums.data(), sums.size()), Error);
  ImageBlock block({0, 0}, {4, 4}, nullptr), other({0, 0}, {5, 4}, nullptr);
  block.pack(sums);
  EXPECT_THROW(other.unpack(sums.data(), sums.size()), Error);
}

}  // namespace
}  // namespace femto
