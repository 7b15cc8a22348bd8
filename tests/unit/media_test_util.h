#pragma once
// Helpers shared by the media and transient path tests: creating media and
// phase functions from XML (so the loader's name upgrades apply), a sampler,
// and a running mean with its standard error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include <femto/render/medium.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"

namespace femto::test {

/// A Mitsuba .vol density grid (float32, one channel) on the box
/// [-halfExtent, halfExtent]^3: `res`^3 vertex samples from 0.1 to 1.5 in a
/// pattern that is neither smooth nor separable, so free flights and
/// transmittance must track it.
inline void writeDensityGrid(const std::filesystem::path& file, int res, float halfExtent) {
  std::ofstream out(file, std::ios::binary);
  out.write("VOL", 3);
  char version = 3;
  out.write(&version, 1);
  int32_t header[5] = {1, res, res, res, 1};
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  float bounds[6] = {-halfExtent, -halfExtent, -halfExtent, halfExtent, halfExtent, halfExtent};
  out.write(reinterpret_cast<const char*>(bounds), sizeof bounds);
  for (int z = 0; z < res; ++z)
    for (int y = 0; y < res; ++y)
      for (int x = 0; x < res; ++x) {
        float density = 0.1f + 1.4f * float((x + 2 * y + 3 * z) % 5) / 4.0f;
        out.write(reinterpret_cast<const char*>(&density), sizeof density);
      }
}

/// Load a whole scene from XML in strict mode (plugins from the build tree);
/// errors name the file `name`.
inline std::shared_ptr<Scene> loadSceneStrict(const std::string& xml,
                                              const std::filesystem::path& dir = std::filesystem::temp_directory_path(),
                                              const std::string& name = "<media test>") {
  usePluginsFromBuildTree();
  LoadOptions options;
  options.strict = true;
  return loadSceneFromString(xml, dir, options, name);
}

/// Load scenes/`name`/scene.xml of the source tree in strict mode with `defines`.
inline std::shared_ptr<Scene> loadShippedSceneStrict(const std::string& name,
                                                     const std::map<std::string, std::string>& defines) {
  usePluginsFromBuildTree();
  LoadOptions options;
  options.strict = true;
  options.defines = defines;
  return loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes" / name / "scene.xml", options);
}

/// The medium with id "m" of a scene whose sensor sits in it:
/// `mediumXml` is a complete <medium id="m" ...>...</medium> element.
inline std::shared_ptr<Scene> sceneWithMedium(const std::string& mediumXml, const std::string& version = "3.0.0",
                                              const std::filesystem::path& dir = std::filesystem::temp_directory_path()) {
  return loadSceneStrict(str("<scene version=\"", version, "\">", mediumXml,
                             "<sensor type=\"perspective\"><ref id=\"m\"/></sensor></scene>"),
                         dir);
}

/// An independent sampler seeded for a test.
inline std::unique_ptr<Sampler> seededSampler(uint64_t seed = 1) {
  Properties props("independent");
  auto prototype = makePlugin<Sampler>(ObjectKind::Sampler, props);
  auto sampler = prototype->clone();
  sampler->startPixel(seed, 0);
  return sampler;
}

/// Mean and standard error of a scalar from running sums.
class Mean {
 public:
  void add(double v) {
    ++n_;
    sum_ += v;
    sumSq_ += v * v;
  }
  double mean() const { return n_ ? sum_ / double(n_) : 0.0; }
  double standardError() const {
    if (n_ < 2) return 0.0;
    double m = mean();
    return std::sqrt(std::max(0.0, (sumSq_ / double(n_) - m * m) / double(n_ - 1)));
  }
  long count() const { return n_; }

 private:
  long n_ = 0;
  double sum_ = 0.0, sumSq_ = 0.0;
};

/// |estimate - expected| within 5 standard errors (plus `slack` for float round-off).
inline void expectWithinErrorBars(const Mean& m, double expected, double slack = 1e-6, const std::string& what = "") {
  EXPECT_NEAR(m.mean(), expected, 5.0 * m.standardError() + slack)
      << what << " standard error " << m.standardError() << " over " << m.count() << " samples";
}

}  // namespace femto::test
