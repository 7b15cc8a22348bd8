// Scenes written in other renderers' dialects (tests/scene/dialects/*.xml:
// Mitsuba 0.6, Mitsuba 3, mitransient, Mitsuba 2's transient renderer), each
// written from that renderer's public documentation and using one of the
// names femto maps (docs/coming-from-mitransient.md). Each must render as a
// user would run it, `femto render FILE --strict`: exit 0, no dropped
// samples, a finite steady image, and for transient films a volume of the
// shape the scene's own time axis gives.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <femto/base/error.h>
#include <femto/image/image_io.h>

#include "run_femto.h"

namespace fs = std::filesystem;
using femto::scenetest::quoted;
using femto::scenetest::run;

namespace {

std::vector<fs::path> dialectScenes() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(FEMTO_DIALECT_SCENES_DIR))
    if (entry.path().extension() == ".xml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// The `<!-- expect-bins: N -->` comment of a transient scene: the bin count
/// its time axis gives, checked against the .npy's shape.
int expectedBins(const fs::path& scene) {
  std::ifstream in(scene);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::smatch m;
  if (std::regex_search(text, m, std::regex(R"(expect-bins:\s*(\d+))"))) return std::stoi(m[1]);
  return 0;
}

/// The shape of a .npy volume from its header, as "16 16 40 3".
std::string npyShape(const fs::path& npy) {
  std::ifstream in(npy, std::ios::binary);
  std::string header(256, '\0');
  in.read(header.data(), std::streamsize(header.size()));
  std::smatch m;
  if (!std::regex_search(header, m, std::regex(R"('shape': \(([^)]*)\))"))) return "";
  std::string dims = m[1], out;
  const std::regex number(R"(\d+)");
  for (std::sregex_iterator it(dims.begin(), dims.end(), number), end; it != end; ++it)
    out += (out.empty() ? "" : " ") + it->str();
  return out;
}

class DialectScene : public ::testing::TestWithParam<fs::path> {};

}  // namespace

TEST_P(DialectScene, RendersStrict) {
  const fs::path& scene = GetParam();
  fs::path dir = fs::temp_directory_path() / ("femto-dialect-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::path out = dir / (scene.stem().string() + ".exr");
  auto r = run(femto::str(FEMTO_EXECUTABLE, " render ", quoted(scene), " --strict --spp 4 -t 2 --no-progress -p ",
                          quoted(FEMTO_PLUGIN_DIR), " -o ", quoted(out)));
  ASSERT_EQ(r.exitCode, 0) << scene.filename() << ":\n" << r.output;
  EXPECT_EQ(r.output.find("were dropped"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  femto::Bitmap image = femto::readImage(out);
  ASSERT_GT(image.width * image.height, 0);
  size_t nonFinite = 0;
  double sum = 0.0;
  for (float v : image.data) nonFinite += !std::isfinite(v), sum += v;
  EXPECT_EQ(nonFinite, 0u);
  EXPECT_GT(sum, 0.0) << "a black image: the scene's light did not arrive";
  if (int bins = expectedBins(scene)) {
    fs::path npy = out;
    npy.replace_extension(".npy");
    ASSERT_TRUE(fs::exists(npy)) << r.output;
    EXPECT_EQ(npyShape(npy), femto::str(image.height, " ", image.width, " ", bins, " 3"));
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Dialects, DialectScene, ::testing::ValuesIn(dialectScenes()),
                         [](const ::testing::TestParamInfo<fs::path>& info) {
                           std::string name = info.param.stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });
