// `femto plugins`: every plugin on the search path, with kind and description.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>

#include <femto/core/plugin.h>

#include "command_options.h"
#include "commands.h"

namespace femto::cli {
namespace {

struct PluginsSettings {
  std::vector<std::string> pluginDirs;
  std::function<void()> applyPluginDirs;
};

int listPlugins(const PluginsSettings& settings) {
  settings.applyPluginDirs();
  PluginManager& manager = PluginManager::instance();
  std::vector<const PluginDescriptor*> plugins = manager.discoverAll();
  if (plugins.empty()) {
    std::cerr << "no plugins found; searched:";
    for (const auto& dir : manager.searchPath()) std::cerr << ' ' << dir.string();
    std::cerr << '\n';
    return 1;
  }
  std::sort(plugins.begin(), plugins.end(), [](const PluginDescriptor* a, const PluginDescriptor* b) {
    return std::pair(int(a->kind), std::string(a->name)) < std::pair(int(b->kind), std::string(b->name));
  });
  size_t nameWidth = 0;
  for (const PluginDescriptor* p : plugins) nameWidth = std::max(nameWidth, std::string(p->name).size());
  for (const PluginDescriptor* p : plugins) {
    std::cout << std::left << std::setw(11) << kindTag(p->kind) << std::setw(int(nameWidth) + 2) << p->name
              << (p->description ? p->description : "") << '\n';
  }
  return 0;
}

}  // namespace

Command addPluginsCommand(CLI::App& app) {
  auto settings = std::make_shared<PluginsSettings>();
  CLI::App* command = app.add_subcommand("plugins", "List the plugins found on the search path (kind, name, description)");
  settings->applyPluginDirs = addPluginDirOption(*command, settings->pluginDirs);
  return [settings] { return listPlugins(*settings); };
}

}  // namespace femto::cli
