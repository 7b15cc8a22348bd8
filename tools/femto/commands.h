#pragma once
// The femto subcommands. Each registers its options on the CLI11 app and
// returns the action that runs it once the command line has been parsed.
#include <functional>

#include <CLI/CLI.hpp>

namespace femto::cli {

/// Runs a parsed subcommand; returns the process exit code.
using Command = std::function<int()>;

Command addRenderCommand(CLI::App& app);
Command addPluginsCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
/// `femto compare SCENE.xml ...` (integrators on a scene, run by a Python
/// engine): is this that form, and run it (replaces the process when it can).
bool isSceneComparison(int argc, char** argv);
int runSceneComparison(int argc, char** argv);
// Looking at transient volumes (docs/viewing.md).
Command addFramesCommand(CLI::App& app);
Command addStreakCommand(CLI::App& app);
Command addIntegrateCommand(CLI::App& app);
Command addProfileCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);

}  // namespace femto::cli
