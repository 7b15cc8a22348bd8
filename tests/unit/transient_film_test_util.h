#pragma once
// Scenes for transient film tests: the test-only film-position sensor and
// ramp integrator (tests/plugins) with a transient (or any) film, built
// without a scene file.
#include <filesystem>
#include <memory>
#include <vector>

#include <femto/core/plugin.h>
#include <femto/film/npy_volume.h>
#include <femto/render/scene.h>

#include "render_test_util.h"

namespace femto::test {

inline std::shared_ptr<Object> makeTestPlugin(ObjectKind kind, const Properties& props) {
  static bool prepared = [] {
    PluginManager::instance().prependSearchPath(FEMTO_TEST_PLUGIN_DIR);
    return true;
  }();
  (void)prepared;
  return makePlugin<Object>(kind, props);
}

/// Scene: `film` (its plugin name set by the caller) seen by test_film_position
/// with `spp` independent samples, rendered by `integrator`.
inline std::shared_ptr<Scene> makeRampScene(const Properties& film, const Properties& integrator, int spp) {
  Properties sampler("independent");
  sampler.setInt("sample_count", spp);
  Properties sensor("test_film_position");
  sensor.setObject("film", makeTestPlugin(ObjectKind::Film, film));
  sensor.setObject("sampler", makeTestPlugin(ObjectKind::Sampler, sampler));
  Properties scene("scene");
  scene.setObject("sensor", makeTestPlugin(ObjectKind::Sensor, sensor));
  scene.setObject("integrator", makeTestPlugin(ObjectKind::Integrator, integrator));
  return std::make_shared<Scene>(scene);
}

/// The whole (h, w, bins, 3) volume of a .npy file written by a transient film.
inline std::vector<float> readVolume(const std::filesystem::path& path, int& h, int& w, int& bins) {
  NpyVolume volume = NpyVolume::open(path);
  h = volume.height(), w = volume.width(), bins = volume.bins();
  std::vector<float> data(size_t(h) * w * bins * 3);
  for (int y = 0; y < h; ++y) volume.readPixels(y, 0, w, &data[size_t(y) * w * bins * 3]);
  return data;
}

}  // namespace femto::test
