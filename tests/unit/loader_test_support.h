#pragma once
// Shared by the loader tests: a factory double that records Properties
// instead of loading plugins, temporary scene folders, and error matching.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <femto/xml/parse_stages.h>

namespace femto::loadertest {

/// What the factory double creates: the kind and the Properties it was given.
class RecordedObject : public Object {
 public:
  RecordedObject(ObjectKind kind, Properties props) : kind_(kind), props(std::move(props)) {}
  ObjectKind kind() const override { return kind_; }
  ObjectKind kind_;
  Properties props;
};

/// Reads every parameter (so nothing is "unused") unless `reads` lists, per
/// plugin name, the only names that plugin asks for.
class RecordingFactory : public xml::ObjectFactory {
 public:
  std::map<std::string, std::vector<std::string>> reads;
  std::function<void(const Properties&)> onCreate;
  ObjectRef create(ObjectKind kind, const Properties& props) override {
    if (onCreate) onCreate(props);
    auto it = reads.find(props.pluginName());
    if (it == reads.end()) {
      for (const auto& n : props.names()) props.markQueried(n);
    } else {
      for (const auto& n : it->second) props.has(n) ? props.markQueried(n) : void();
    }
    return std::make_shared<RecordedObject>(kind, props);
  }
};

inline const RecordedObject& recorded(const ObjectRef& o) { return dynamic_cast<const RecordedObject&>(*o); }

/// Parse (stages 1-4) and build (stage 5) with the double.
inline std::shared_ptr<RecordedObject> buildRecorded(const std::string& xml, const LoadOptions& options = {},
                                                     RecordingFactory* factory = nullptr,
                                                     const std::filesystem::path& dir = ".") {
  RecordingFactory local;
  auto parsed = xml::parseString(xml, dir, options, "test.xml");
  return std::dynamic_pointer_cast<RecordedObject>(xml::buildObject(parsed, options, factory ? *factory : local));
}

/// A fresh empty folder under the test temp dir.
inline std::filesystem::path freshDir(const std::string& name) {
  auto dir = std::filesystem::path(::testing::TempDir()) / ("femto_loader_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void writeFile(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

/// The message of the femto::Error `f` throws ("" when it does not throw).
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace femto::loadertest

/// The error starts with "file:line: " and contains `text`.
#define EXPECT_SCENE_ERROR(statement, fileLine, text)                                         \
  do {                                                                                        \
    std::string message_ = ::femto::loadertest::errorOf([&] { statement; });                     \
    EXPECT_EQ(message_.rfind(std::string(fileLine) + ": ", 0), 0u) << message_;               \
    EXPECT_NE(message_.find(text), std::string::npos) << message_;                            \
  } while (0)
