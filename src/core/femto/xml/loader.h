#pragma once
// Scene loading from Mitsuba XML, 0.4-0.6 dialect (version < 2) and Mitsuba 3
// dialect (version >= 2). Parsing happens in stages (see parser stages in
// xml/*.cpp): XML -> nodes with file:line -> includes/defaults/$name ->
// legacy name upgrade -> refs -> objects. Every error names file and line and
// echoes the offending line.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <femto/core/object.h>
#include <femto/math/vector.h>

namespace femto {

class Scene;

struct LoadOptions {
  /// -D name=value: override <default> values and define $name.
  std::map<std::string, std::string> defines;
  /// Parameters nobody read are errors instead of warnings.
  bool strict = false;
  /// --resolution WxH: overrides the film's width/height.
  std::optional<Point2i> resolution;
  /// --spp N: overrides the sampler's sample_count.
  std::optional<int> sampleCount;
  /// --integrator FILE: the scene's integrator is replaced by the one this
  /// file holds (a <scene> with an <integrator>, like the fog box's
  /// integrator-*.xml, or an <integrator> root). It is included after the
  /// scene's own elements: it may use the scene's $names, and its
  /// <default>s only set names the scene and -D do not.
  std::optional<std::filesystem::path> integratorFile;
};

/// Load a scene file. Throws femto::Error ("file:line: message\n  <line text>") on bad input.
std::shared_ptr<Scene> loadScene(const std::filesystem::path& file, const LoadOptions& options = {});
/// Load from a string; relative files (meshes, includes) resolve against `baseDir`.
/// `virtualName` is the file name used in messages.
std::shared_ptr<Scene> loadSceneFromString(const std::string& xml, const std::filesystem::path& baseDir,
                                           const LoadOptions& options = {},
                                           const std::string& virtualName = "<string>");
/// Load a single object of any kind (root element <bsdf>, <shape>, ...), for tests and tools.
ObjectRef loadObjectFromString(const std::string& xml, const std::filesystem::path& baseDir,
                               const LoadOptions& options = {}, const std::string& virtualName = "<string>");

}  // namespace femto
