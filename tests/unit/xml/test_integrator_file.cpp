// LoadOptions::integratorFile (`femto render --integrator FILE.xml`, `femto
// compare SCENE -i FILE.xml`) on a real scene: the fog box's integrator, which
// its scene.xml includes by $integrator, is replaced by the file's.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <femto/render/integrator.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"

using namespace femto;

namespace {

const std::filesystem::path FogBox = std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box-fog";

std::shared_ptr<Scene> loadFog(const std::optional<std::filesystem::path>& integratorFile) {
  LoadOptions options;
  options.strict = true;
  options.defines = {{"resolution", "8"}, {"bins", "8"}, {"bin_width", "1.28"}, {"frames", "false"}, {"spp", "1"}};
  if (integratorFile && integratorFile->filename() == "integrator-transient_beams.xml")
    options.defines.insert({{"photon_count", "500"}, {"beam_photon_count", "100"}});
  options.integratorFile = integratorFile;
  return loadScene(FogBox / "scene.xml", options);
}

std::string bytesOf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(IntegratorFile, ReplacesTheScenesIntegrator) {
  // The scene's default is transient_path; the file's is transient_beams,
  // with the scene's $max_depth, $passes, ... (its defaults after the scene's).
  auto scene = loadFog(FogBox / "integrator-transient_beams.xml");
  EXPECT_NE(scene->integrator().toString().find("TransientBeamsIntegrator"), std::string::npos)
      << scene->integrator().toString();
}

TEST(IntegratorFile, TheScenesOwnIntegratorFileRendersTheSameBits) {
  auto dir = test::scratchDir("integrator-file");
  RenderOptions options;
  options.progress = false;
  options.output = dir / "scene.exr";
  auto plain = loadFog(std::nullopt);
  plain->integrator().render(*plain, options);
  options.output = dir / "file.exr";
  auto viaFile = loadFog(FogBox / "integrator-transient_path.xml");
  viaFile->integrator().render(*viaFile, options);
  EXPECT_EQ(bytesOf(dir / "scene.npy"), bytesOf(dir / "file.npy"));
  EXPECT_FALSE(bytesOf(dir / "scene.npy").empty());
  std::filesystem::remove_all(dir);
}

}  // namespace
