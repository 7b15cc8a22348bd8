#pragma once
// Options several femto subcommands share, set up once: the same name, value
// type, check and placeholder wherever they appear (see also view_options.h
// for the commands that look at a transient volume).
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace femto::cli {

/// Adds `-p,--plugin-dir DIR` (repeatable) to `command`; the returned action puts
/// the directories first in the plugin search path, in the order given.
std::function<void()> addPluginDirOption(CLI::App& command, std::vector<std::string>& dirs);

/// `-o,--output NAME`: where the command writes (`help` says the default),
/// shown as `typeName` (FILE, DIR, STEM).
CLI::Option* addOutputOption(CLI::App& command, std::string& output, const std::string& help,
                             const std::string& typeName = "FILE");

/// A count (threads, samples, frames): a whole number >= 1 (PositiveInteger),
/// shown as `typeName`.
CLI::Option* addCountOption(CLI::App& command, const std::string& name, int& count, const std::string& help,
                            const std::string& typeName = "N");

/// `--bins FIRST:END`: a range of time bins, parsed by the command.
CLI::Option* addBinRangeOption(CLI::App& command, std::string& bins, const std::string& help);

/// The positional `volume`: a transient volume (.npy) that must exist.
CLI::Option* addVolumeArgument(CLI::App& command, std::string& volume);

}  // namespace femto::cli
