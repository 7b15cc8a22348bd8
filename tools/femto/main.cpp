// femto: the command-line renderer. Subcommands live in *_command.cpp; this
// file only parses, dispatches and turns failures into one-line errors.
#include <malloc.h>

#include <cstdlib>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include <femto/base/error.h>
#include <femto/core/plugin.h>

#include <string>
#include <vector>

#include <femto/core/spelling.h>

#include "arguments.h"
#include "commands.h"

namespace {

/// `femto rendr ...`: name the word and the nearest command, rather than
/// CLI11's "A subcommand is required". Empty when argv[1] is an option or a command.
std::string unknownCommand(int argc, char** argv, const CLI::App& app) {
  if (argc < 2 || argv[1][0] == '-') return "";
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  const std::string word = argv[1];
  for (const std::string& name : names)
    if (name == word) return "";
  std::string hint = femto::didYouMean(word, names);
  if (hint.empty()) {
    hint = " (commands:";
    for (const std::string& name : names) hint += " " + name;
    hint += ")";
  }
  return femto::str("error: unknown command \"", word, "\"", hint, "\nRun `femto --help` for the commands.\n");
}

/// Transient tiles hold bins x 12 bytes a pixel (50 MB for 32 x 32 pixels at
/// 4096 bins) and are made and freed by the thousand. Above glibc's 32 MB
/// dynamic threshold each would be mapped and unmapped, the kernel faulting in
/// and zeroing every page again; kept in the heap they are reused. Measured
/// (tools/bench/tile_heap.sh): transient_beams at 256 x 256 x 4096, 4 passes,
/// 1.38x less wall time (system CPU 13.4 -> 4.5 s). Not when the user tunes malloc (GLIBC_TUNABLES).
void keepLargeBlocksInTheHeap() {
  if (std::getenv("GLIBC_TUNABLES")) return;
  mallopt(M_MMAP_THRESHOLD, 512 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace

int main(int argc, char** argv) {
  keepLargeBlocksInTheHeap();
  CLI::App app{"femto: a physically based renderer for (time-resolved) light transport", "femto"};
  app.set_version_flag("--version", femto::str("femto ", FEMTO_VERSION, " (plugin ABI ", femto::FemtoAbiVersion, ')'));
  app.require_subcommand(1);
  app.footer("Run `femto <command> --help` for the options of a command.");
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return femto::str("error: ", e.what(), "\nRun `femto --help` or `femto <command> --help` for the options.\n");
  });

  femto::cli::Command render = femto::cli::addRenderCommand(app);
  femto::cli::Command plugins = femto::cli::addPluginsCommand(app);
  femto::cli::Command compare = femto::cli::addCompareCommand(app);
  femto::cli::Command frames = femto::cli::addFramesCommand(app);
  femto::cli::Command streak = femto::cli::addStreakCommand(app);
  femto::cli::Command integrate = femto::cli::addIntegrateCommand(app);
  femto::cli::Command profile = femto::cli::addProfileCommand(app);
  femto::cli::Command view = femto::cli::addViewCommand(app);

  if (femto::cli::isSceneComparison(argc, argv)) return femto::cli::runSceneComparison(argc, argv);
  if (std::string message = unknownCommand(argc, argv, app); !message.empty()) {
    std::cerr << message;
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; bad arguments print the problem and exit 2
    // (the usual code for usage errors), distinct from a failed render (1).
    return app.exit(e) == 0 ? 0 : 2;
  }

  try {
    if (app.got_subcommand("render")) return render();
    if (app.got_subcommand("plugins")) return plugins();
    if (app.got_subcommand("compare")) return compare();
    if (app.got_subcommand("frames")) return frames();
    if (app.got_subcommand("streak")) return streak();
    if (app.got_subcommand("integrate")) return integrate();
    if (app.got_subcommand("profile")) return profile();
    if (app.got_subcommand("view")) return view();
    return 1;  // unreachable: require_subcommand(1)
  } catch (const femto::cli::UsageError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  } catch (const femto::Error& e) {
    std::cerr << "error: " << e.what() << '\n';
  } catch (const std::exception& e) {
    // Not a user error: still one line, never a crash or a stack trace.
    std::cerr << "error: internal error: " << e.what() << '\n';
  }
  return 1;
}
