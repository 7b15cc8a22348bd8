// A render with a time limit (RenderOptions::timeLimit, `femto render
// --time-limit`) renders whole passes and is bitwise the render asked for the
// passes it reached: for transient_path (passes of the sampler's spp) and
// transient_beams, into a transient film and a steady one. Nothing here
// asserts a time: the count reached is read back and rendered again.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include <femto/film/volume_info.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "plugin_util.h"
#include "transient_film_test_util.h"

using namespace femto;

namespace {

std::string bytesOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// scenes/cornell-box-fog at 12x12, 16 bins, with `integrator` and its small settings.
std::shared_ptr<Scene> tinyFog(const std::string& integrator, const std::string& film = "transient") {
  LoadOptions options;
  options.strict = true;
  options.defines = {{"resolution", "12"}, {"integrator", integrator}, {"film", film}};
  if (film == "transient") options.defines.insert({{"bins", "16"}, {"bin_width", "0.64"}, {"frames", "false"}});
  if (integrator == "transient_beams")
    options.defines.insert({{"photon_count", "2000"}, {"beam_photon_count", "300"}, {"spp", "2"}});
  else
    options.defines.insert({"spp", "1"});
  return loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box-fog/scene.xml", options);
}

RenderStats renderTo(const Scene& scene, const std::filesystem::path& out, int passes, double timeLimit) {
  RenderOptions options;
  options.output = out;
  options.progress = false;
  options.seed = 5;
  options.passes = passes;
  options.timeLimit = timeLimit;
  options.timeClock = RenderClock::Cpu;
  return scene.integrator().render(scene, options);
}

/// Time-limited, then the count it reached without a limit: the same files.
void expectLimitedEqualsCount(const std::string& integrator, const std::string& film, double limit, int cap) {
  auto dir = test::scratchDir("time-limit-" + integrator + "-" + film);
  auto scene = tinyFog(integrator, film);
  RenderStats limited = renderTo(*scene, dir / "limited.exr", cap, limit);
  ASSERT_TRUE(limited.completed);
  ASSERT_GE(limited.passes, 1);
  if (cap > 0) EXPECT_EQ(limited.passes, cap);  // the limit (an hour) never ends it first
  RenderStats counted = renderTo(*scene, dir / "counted.exr", limited.passes, 0.0);
  EXPECT_EQ(counted.passes, limited.passes);
  EXPECT_EQ(counted.samples, limited.samples);
  EXPECT_EQ(bytesOf(dir / "limited.exr"), bytesOf(dir / "counted.exr")) << integrator << ", " << limited.passes
                                                                           << " passes";
  if (film == "transient") {
    EXPECT_EQ(bytesOf(dir / "limited.npy"), bytesOf(dir / "counted.npy")) << integrator;
    // The sidecar says what was reached, and that the limit was set.
    std::optional<VolumeInfo> info = readVolumeInfo(dir / "limited.npy");
    ASSERT_TRUE(info && info->render);
    EXPECT_EQ(info->render->passes, limited.passes);
    EXPECT_EQ(info->render->samplesPerPass, int(scene->sensor().sampler().sampleCount()));
    EXPECT_EQ(info->render->seed, 5u);
    EXPECT_EQ(info->render->timeLimit, limit);
    EXPECT_EQ(info->render->timeClock, "cpu");
    EXPECT_EQ(info->render->timeLimitReached, limited.timeLimitReached);
  }
  std::filesystem::remove_all(dir);
}

TEST(TimeLimitedRender, TransientPathEqualsTheRenderOfThePassesReached) {
  expectLimitedEqualsCount("transient_path", "transient", 0.4, 0);
  // Capped below the limit: several passes for certain, whatever the machine's load.
  expectLimitedEqualsCount("transient_path", "transient", 3600.0, 3);
}

TEST(TimeLimitedRender, TransientBeamsEqualsTheRenderOfThePassesReached) {
  expectLimitedEqualsCount("transient_beams", "transient", 0.4, 0);
  expectLimitedEqualsCount("transient_beams", "transient", 3600.0, 3);
}

TEST(TimeLimitedRender, SteadyFilmEqualsTheRenderOfThePassesReached) {
  expectLimitedEqualsCount("transient_path", "hdrfilm", 3600.0, 3);
  expectLimitedEqualsCount("transient_beams", "hdrfilm", 0.4, 0);
}

TEST(TimeLimitedRender, PassesAreIndependentRendersAveraged) {
  // --passes 1 is the ordinary render; pass 2 has other seeds, so 2 passes differ from it.
  auto dir = test::scratchDir("time-limit-passes");
  auto scene = tinyFog("transient_path");
  renderTo(*scene, dir / "plain.exr", 0, 0.0);
  renderTo(*scene, dir / "one.exr", 1, 0.0);
  RenderStats two = renderTo(*scene, dir / "two.exr", 2, 0.0);
  EXPECT_EQ(bytesOf(dir / "plain.npy"), bytesOf(dir / "one.npy"));
  EXPECT_NE(bytesOf(dir / "plain.npy"), bytesOf(dir / "two.npy"));
  EXPECT_EQ(two.passes, 2);
  EXPECT_EQ(two.samples, 2u * 12u * 12u);
  std::filesystem::remove_all(dir);
}

}  // namespace
