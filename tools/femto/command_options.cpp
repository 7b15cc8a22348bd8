#include "command_options.h"

#include "arguments.h"

namespace femto::cli {

CLI::Option* addOutputOption(CLI::App& command, std::string& output, const std::string& help,
                             const std::string& typeName) {
  return command.add_option("-o,--output", output, help)->type_name(typeName);
}

CLI::Option* addCountOption(CLI::App& command, const std::string& name, int& count, const std::string& help,
                            const std::string& typeName) {
  return command.add_option(name, count, help)->type_name(typeName)->check(PositiveInteger);
}

CLI::Option* addBinRangeOption(CLI::App& command, std::string& bins, const std::string& help) {
  return command.add_option("--bins", bins, help)->type_name("FIRST:END");
}

CLI::Option* addVolumeArgument(CLI::App& command, std::string& volume) {
  return command.add_option("volume", volume, "Transient volume written by a transient film (out.npy)")
      ->required()
      ->check(CLI::ExistingFile);
}

}  // namespace femto::cli
