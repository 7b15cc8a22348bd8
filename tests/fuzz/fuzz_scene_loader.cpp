// libFuzzer target over the scene loader and its value parsers: any byte
// string is loaded as a scene (both dialects, defines, includes, references,
// every plugin's parameter parsing). A femto::Error is the expected answer to
// bad input; anything else -- a crash, a sanitizer report, another exception
// type escaping, a hang, an allocation over libFuzzer's limit -- is a finding.
// Built by tools/fuzz/run_scene_fuzzer.sh (clang, -DFEMTO_FUZZ=ON).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <femto/base/error.h>
#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/xml/loader.h>

namespace {

// Relative includes and meshes resolve against the corpus folder the script
// copies real scenes into (FEMTO_FUZZ_BASE_DIR), so references can succeed.
std::filesystem::path baseDir() {
  const char* dir = std::getenv("FEMTO_FUZZ_BASE_DIR");
  return dir ? std::filesystem::path(dir) : std::filesystem::temp_directory_path();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  femto::setLogLevel(femto::LogLevel::Error);  // warnings about unused parameters would dominate the run time
  if (const char* plugins = std::getenv("FEMTO_PLUGIN_PATH")) femto::PluginManager::instance().prependSearchPath(plugins);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::filesystem::path base = baseDir();
  const std::string xml(reinterpret_cast<const char*>(data), size);
  try {
    femto::loadSceneFromString(xml, base);
  } catch (const femto::Error&) {
    // The located error a user sees: the intended outcome for bad input.
  }
  return 0;
}
