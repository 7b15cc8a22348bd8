// Surface-only integrators (path, direct) do not trace participating media.
// Rendering a foggy scene with them must say so instead of silently giving
// an image without its fog (the project's "no silently wrong image" rule).
#include <gtest/gtest.h>

#include <femto/render/integrator.h>
#include <femto/render/scene.h>
#include <femto/transport/volumetric.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"

namespace femto {
namespace {

struct Outcome {
  bool hasMedia;
  std::string log;
};

/// scenes/cornell-box-fog at 4x4 with `integrator` on a steady film.
Outcome renderFogBox(const std::string& integrator, const std::string& medium) {
  LoadOptions options;
  options.strict = true;
  options.defines = {{"integrator", integrator}, {"medium", medium}, {"film", "hdrfilm"},
                     {"resolution", "4"},        {"spp", "1"}};
  auto scene = loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box-fog/scene.xml", options);
  RenderOptions render;
  render.output = test::scratchDir("media-ignored-" + integrator + "-" + medium) / "out.exr";
  render.progress = false;
  testing::internal::CaptureStderr();
  scene->integrator().render(*scene, render);
  return {sceneHasMedia(*scene), testing::internal::GetCapturedStderr()};
}

TEST(MediaIgnoredWarning, PathWarnsOnAFoggySceneOnly) {
  Outcome fog = renderFogBox("path", "fog");
  EXPECT_TRUE(fog.hasMedia);
  EXPECT_NE(fog.log.find("path: the scene has participating media, which this integrator ignores"), std::string::npos)
      << fog.log;
  Outcome clear = renderFogBox("path", "none");
  EXPECT_FALSE(clear.hasMedia);
  EXPECT_EQ(clear.log.find("participating media"), std::string::npos) << clear.log;
}

TEST(MediaIgnoredWarning, TransientPathTracesMediaAndDoesNotWarn) {
  Outcome fog = renderFogBox("transient_path", "fog");
  EXPECT_TRUE(fog.hasMedia);
  EXPECT_EQ(fog.log.find("participating media"), std::string::npos) << fog.log;
}

}  // namespace
}  // namespace femto
