#include <femto/core/plugin.h>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include <femto/base/error.h>
#include <femto/core/log.h>
#include <femto/core/spelling.h>

namespace fs = std::filesystem;

namespace femto {

// One opened plugin library. Never dlclose'd: objects it created (and their
// vtables) may live until the process exits.
struct PluginManager::Library {
  std::string name;
  fs::path file;
  void* handle = nullptr;
  const PluginDescriptor* descriptor = nullptr;
};

namespace {

fs::path executableDir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

std::vector<fs::path> splitPathList(const char* list) {
  std::vector<fs::path> dirs;
  if (!list) return dirs;
  std::string s(list);
  size_t start = 0;
  while (start <= s.size()) {
    size_t end = s.find(':', start);
    if (end == std::string::npos) end = s.size();
    if (end > start) dirs.emplace_back(s.substr(start, end - start));
    start = end + 1;
  }
  return dirs;
}

/// ObjectKind values outside the known range come from a corrupt or newer
/// plugin; kindTag() is the single list of known kinds.
bool knownKind(ObjectKind kind) {
  try {
    kindTag(kind);
    return true;
  } catch (const std::out_of_range&) {
    return false;
  }
}

std::string quoted(const std::string& s) { return '"' + s + '"'; }

std::string joinPaths(const std::vector<fs::path>& dirs) {
  if (dirs.empty()) return "(no directories: set FEMTO_PLUGIN_PATH or pass -p DIR)";
  std::string out;
  for (size_t i = 0; i < dirs.size(); ++i) out += (i ? ", " : "") + dirs[i].string();
  return out;
}

}  // namespace

std::string pluginFileName(const std::string& name) { return name + ".so"; }

bool PluginManager::validName(const std::string& name) {
  if (name.empty() || name.size() > 128) return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

PluginManager::PluginManager() {
  if (fs::path exeDir = executableDir(); !exeDir.empty()) {
    searchPath_.push_back(exeDir / "plugins");
    // <prefix>/bin/femto finds <prefix>/lib/femto/plugins (the libdir the build was configured with).
    searchPath_.push_back((exeDir / ".." / FEMTO_INSTALLED_PLUGIN_DIR).lexically_normal());
  }
  for (fs::path& dir : splitPathList(std::getenv("FEMTO_PLUGIN_PATH"))) searchPath_.push_back(std::move(dir));
}

PluginManager& PluginManager::instance() {
  static PluginManager manager;
  return manager;
}

void PluginManager::prependSearchPath(const fs::path& dir) {
  std::lock_guard<std::mutex> lock(mutex_);
  searchPath_.insert(searchPath_.begin(), dir);
}

const PluginDescriptor& PluginManager::load(const std::string& name) {
  if (!validName(name))
    throw Error(str("invalid plugin name ", quoted(name),
                    ": plugin names contain only letters, digits, '_' and '-' (no paths or file extensions)"));
  std::unique_lock<std::mutex> lock(mutex_);
  for (const auto& library : libraries_)
    if (library->name == name) return *library->descriptor;
  for (const fs::path& dir : searchPath_) {
    fs::path candidate = dir / pluginFileName(name);
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return openLocked(candidate);
  }
  std::vector<fs::path> searched = searchPath_;
  lock.unlock();
  throw Error(str("plugin ", quoted(name), " not found: no ", pluginFileName(name), " in ", joinPaths(searched),
                  didYouMean(name, availableNames())));
}

const PluginDescriptor& PluginManager::loadFile(const fs::path& file) {
  std::lock_guard<std::mutex> lock(mutex_);
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(file, ec);
  if (ec) canonical = file;
  for (const auto& library : libraries_)
    if (library->file == canonical) return *library->descriptor;
  return openLocked(canonical);
}

// Opens `file`, checks it is a femto plugin of this ABI named like its file,
// and records it. Caller holds mutex_.
const PluginDescriptor& PluginManager::openLocked(const fs::path& file) {
  const std::string name = file.stem().string();
  const std::string who = str("plugin ", quoted(name), " (", file.string(), ")");
  for (const auto& library : libraries_)
    if (library->name == name)
      throw Error(str(who, " cannot be loaded: a plugin of that name is already loaded from ", library->file.string()));

  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* reason = dlerror();
    throw Error(str(who, " could not be loaded: ", reason ? reason : "unknown dlopen error"));
  }
  auto fail = [&](const std::string& message) -> Error {
    dlclose(handle);
    return Error(str(who, ' ', message));
  };
  using Entry = const PluginDescriptor* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, PluginEntryPoint));
  if (!entry) throw fail(str("is not a femto plugin: it does not export ", PluginEntryPoint, " (use FEMTO_EXPORT_PLUGIN)"));
  const PluginDescriptor* descriptor = entry();
  if (!descriptor) throw fail(str("is not a usable femto plugin: ", PluginEntryPoint, " returned null"));
  // abiVersion is the descriptor's first field and is checked before any other
  // field is read: the rest of the layout may differ under another ABI.
  if (descriptor->abiVersion != FemtoAbiVersion)
    throw fail(str("was built for femto plugin ABI ", descriptor->abiVersion, ", this femto has ABI ", FemtoAbiVersion,
                   ": rebuild it"));
  if (!descriptor->name || !descriptor->create || !knownKind(descriptor->kind))
    throw fail("has an incomplete descriptor (name, kind and create function are required)");
  if (name != descriptor->name)
    throw fail(str("declares the name ", quoted(descriptor->name),
                   "; a plugin's name must match its file name (rename the file to ", pluginFileName(descriptor->name),
                   " or fix the name in FEMTO_EXPORT_PLUGIN)"));

  auto library = std::make_unique<Library>();
  library->name = name;
  library->file = file;
  library->handle = handle;
  library->descriptor = descriptor;
  libraries_.push_back(std::move(library));
  logDebug("loaded ", who);
  return *descriptor;
}

ObjectRef PluginManager::create(ObjectKind expected, const Properties& props) {
  const PluginDescriptor& descriptor = load(props.pluginName());
  const std::string& name = props.pluginName();
  if (descriptor.kind != expected)
    throw Error(props.location(), str("plugin ", quoted(name), " creates a <", kindTag(descriptor.kind),
                                      ">, but it is used here as a <", kindTag(expected), '>'));
  ObjectRef object;
  try {
    object.reset(descriptor.create(props));
    if (object) object->readCommonParameters(props);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(props.location(), str("plugin ", quoted(name), " failed to create its object: ", e.what()));
  }
  if (!object) throw Error(props.location(), str("plugin ", quoted(name), " returned no object"));
  if (object->kind() != expected)
    throw Error(props.location(), str("plugin ", quoted(name), " declares kind <", kindTag(expected),
                                      "> but created a <", kindTag(object->kind()), ">"));
  if (!props.id().empty()) object->setId(props.id());
  return object;
}

std::vector<std::string> PluginManager::loadedPlugins() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> names;
  for (const auto& library : libraries_) names.push_back(library->name);
  return names;
}

std::vector<std::string> PluginManager::availableNames() const {
  std::vector<fs::path> dirs;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    dirs = searchPath_;
  }
  std::set<std::string> names;
  for (const fs::path& dir : dirs) {
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
      const fs::path& file = it->path();
      if (file.extension() != ".so" || !it->is_regular_file(ec)) continue;
      if (std::string stem = file.stem().string(); validName(stem)) names.insert(stem);
    }
  }
  return {names.begin(), names.end()};
}

std::vector<const PluginDescriptor*> PluginManager::discoverAll() {
  std::vector<const PluginDescriptor*> found;
  for (const std::string& name : availableNames()) {
    try {
      found.push_back(&load(name));
    } catch (const Error& e) {
      logWarn("skipped: ", e.what());
    }
  }
  return found;
}

}  // namespace femto
