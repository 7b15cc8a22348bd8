// Other renderers' sampler names (Mitsuba 3's multijitter and orthogonal,
// Mitsuba 0.6's halton, hammersley and sobol) load in strict mode with their
// parameters and render as the sampler they stand for; Mitsuba 3's `seed`
// changes the camera samples, deterministically, and seed 0 is the default.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include <femto/loop/render_loop.h>
#include <femto/render/integrator.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"

namespace femto {
namespace {

std::string sceneWithSampler(const std::string& sampler, const std::string& version = "3.0.0") {
  return "<scene version=\"" + version + "\"><integrator type=\"path\"/><sensor type=\"perspective\">"
         "<transform name=\"to_world\"><lookat origin=\"0, 0, 3\" target=\"0, 0, 0\" up=\"0, 1, 0\"/></transform>" +
         sampler +
         "<film type=\"hdrfilm\"><integer name=\"width\" value=\"8\"/><integer name=\"height\" value=\"8\"/>"
         "<rfilter type=\"box\"/></film></sensor><shape type=\"sphere\"><bsdf type=\"diffuse\"/></shape>"
         "<emitter type=\"constant\"/></scene>";
}

std::string renderBytes(const std::string& xml, const std::string& name) {
  LoadOptions load;
  load.strict = true;
  auto scene = loadSceneFromString(xml, ".", load, "sampler.xml");
  auto dir = test::scratchDir("sampler-names-" + name);
  RenderOptions options;
  options.output = dir / "out.exr";
  options.progress = false;
  options.seed = 2;
  scene->integrator().render(*scene, options);
  std::ifstream in(dir / "out.exr", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::filesystem::remove_all(dir);
  return bytes;
}

}  // namespace

TEST(SamplerNames, OtherRenderersNamesRenderAsTheSamplerTheyStandFor) {
  const std::string stratified = renderBytes(
      sceneWithSampler("<sampler type=\"stratified\"><integer name=\"sample_count\" value=\"4\"/></sampler>"), "s");
  for (const char* type : {"multijitter", "orthogonal"}) {
    std::string extra = std::string(type) == "orthogonal" ? "<integer name=\"strength\" value=\"2\"/>" : "";
    EXPECT_EQ(renderBytes(sceneWithSampler(std::string("<sampler type=\"") + type +
                                           "\"><integer name=\"sample_count\" value=\"4\"/>"
                                           "<boolean name=\"jitter\" value=\"true\"/>" + extra + "</sampler>"),
                          type),
              stratified)
        << type;
  }
  const std::string ld = renderBytes(
      sceneWithSampler("<sampler type=\"ldsampler\"><integer name=\"sample_count\" value=\"4\"/></sampler>"), "ld");
  for (const char* type : {"halton", "hammersley", "sobol"})
    EXPECT_EQ(renderBytes(sceneWithSampler(std::string("<sampler type=\"") + type +
                                               "\"><integer name=\"sampleCount\" value=\"4\"/>"
                                               "<integer name=\"scramble\" value=\"-1\"/></sampler>",
                                           "0.6.0"),
                          type),
              ld)
        << type;
}

TEST(SamplerNames, Mitsuba3SeedChangesTheCameraSamplesDeterministically) {
  auto withSeed = [](int seed) {
    return sceneWithSampler("<sampler type=\"independent\"><integer name=\"sample_count\" value=\"2\"/>"
                            "<integer name=\"seed\" value=\"" + std::to_string(seed) + "\"/></sampler>");
  };
  const std::string none = renderBytes(
      sceneWithSampler("<sampler type=\"independent\"><integer name=\"sample_count\" value=\"2\"/></sampler>"), "n");
  EXPECT_EQ(renderBytes(withSeed(0), "0"), none) << "seed 0 is the default";
  const std::string five = renderBytes(withSeed(5), "5");
  EXPECT_NE(five, none);
  EXPECT_EQ(renderBytes(withSeed(5), "5b"), five);
  std::string message;
  try {
    renderBytes(sceneWithSampler("<sampler type=\"independent\">\n<integer name=\"seed\" value=\"-1\"/></sampler>"), "bad");
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_EQ(message.rfind("sampler.xml:2: ", 0), 0u) << message;
}

}  // namespace femto
