#include <femto/xml/loader.h>

#include <femto/render/scene.h>

#include "parse_stages.h"

namespace femto {
namespace fs = std::filesystem;

namespace {

std::shared_ptr<Scene> buildScene(const xml::ParsedScene& parsed, const LoadOptions& options) {
  if (parsed.root.tag != "scene")
    throw xml::sceneError(parsed.root, str("the root element must be <scene>, got <", parsed.root.tag, ">"));
  auto factory = xml::makePluginFactory();
  return std::dynamic_pointer_cast<Scene>(xml::buildObject(parsed, options, *factory));
}

}  // namespace

std::shared_ptr<Scene> loadScene(const fs::path& file, const LoadOptions& options) {
  return buildScene(xml::parseFile(file, options), options);
}

std::shared_ptr<Scene> loadSceneFromString(const std::string& xml, const fs::path& baseDir, const LoadOptions& options,
                                           const std::string& virtualName) {
  return buildScene(xml::parseString(xml, baseDir, options, virtualName), options);
}

ObjectRef loadObjectFromString(const std::string& xml, const fs::path& baseDir, const LoadOptions& options,
                               const std::string& virtualName) {
  auto factory = xml::makePluginFactory();
  return xml::buildObject(xml::parseString(xml, baseDir, options, virtualName), options, *factory);
}

}  // namespace femto
