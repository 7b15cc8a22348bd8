// `femto view out.npy [more.npy ...]`: the interactive viewer in a browser
// (docs/viewing.md). Serves the page and the volumes on 127.0.0.1 until
// interrupted; the server and the page are femto_view's (viewer/).
#include <spawn.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <femto/viewer/view_server.h>

#include "commands.h"

extern char** environ;

namespace femto::cli {
namespace {

struct ViewSettings {
  std::vector<std::string> volumes;
  int port = 0;
  bool noBrowser = false;
};

/// Start the desktop's browser on `url` without waiting for it: $BROWSER,
/// else xdg-open, and only where there is a display to show it on (a
/// machine reached by ssh gets the URL to open on its own side).
void openBrowser(const std::string& url) {
  if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) return;
  const char* browser = std::getenv("BROWSER");
  std::string program = browser && *browser ? browser : "xdg-open";
  char* argv[] = {program.data(), const_cast<char*>(url.c_str()), nullptr};
  pid_t pid = 0;
  if (posix_spawnp(&pid, program.c_str(), nullptr, nullptr, argv, environ) != 0)
    std::cout << "(no browser found to open it: " << program << ")" << std::endl;
}

int view(const ViewSettings& settings) {
  std::vector<std::unique_ptr<ViewedRender>> renders;
  for (const std::string& volume : settings.volumes) renders.push_back(std::make_unique<ViewedRender>(volume));
  ViewServer server(std::move(renders));
  const int port = server.bind(settings.port);
  const std::string url = str("http://127.0.0.1:", port, "/");
  std::cout << "femto view: " << url << " (Ctrl-C to stop)" << std::endl;
  if (!settings.noBrowser) openBrowser(url);
  server.run();
  return 0;
}

}  // namespace

Command addViewCommand(CLI::App& app) {
  auto settings = std::make_shared<ViewSettings>();
  CLI::App* command = app.add_subcommand(
      "view", "Look at transient volumes in a browser: time slider, exposure, pixel profiles, streaks, comparisons");
  command->add_option("volumes", settings->volumes, "Transient volumes (.npy), shown and compared in the page")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--port", settings->port, "Port on 127.0.0.1 (default: a free one)")
      ->type_name("N")
      ->check(CLI::Range(0, 65535));
  command->add_flag("--no-browser", settings->noBrowser, "Only print the URL; do not start a browser");
  return [settings] { return view(*settings); };
}

}  // namespace femto::cli
