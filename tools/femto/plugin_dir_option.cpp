#include <filesystem>

#include <femto/base/error.h>
#include <femto/core/plugin.h>

#include "command_options.h"

namespace femto::cli {

std::function<void()> addPluginDirOption(CLI::App& command, std::vector<std::string>& dirs) {
  command.add_option("-p,--plugin-dir", dirs, "Search DIR for plugins before the default directories (repeatable)")
      ->type_name("DIR")
      ->allow_extra_args(false);
  return [&dirs] {
    for (const std::string& dir : dirs)
      if (std::error_code ec; !std::filesystem::is_directory(dir, ec))
        throw Error(str("plugin directory \"", dir, "\" (-p) does not exist or is not a directory"));
    // Prepending in reverse keeps the first -p first in the search path.
    for (auto it = dirs.rbegin(); it != dirs.rend(); ++it) PluginManager::instance().prependSearchPath(*it);
  };
}

}  // namespace femto::cli
