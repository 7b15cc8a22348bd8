// `femto integrate out.npy`: the running integral over time of a transient
// volume (the continuous-emission view of a pulse render) as a new volume.
#include <filesystem>
#include <iostream>
#include <memory>

#include <femto/film/npy_volume.h>
#include <femto/film/volume_info.h>
#include <femto/view/running_integral.h>

#include "command_options.h"
#include "commands.h"

namespace fs = std::filesystem;

namespace femto::cli {
namespace {

struct IntegrateSettings {
  std::string volume;
  std::string output;
};

int integrate(const IntegrateSettings& settings) {
  const NpyVolume volume = NpyVolume::open(settings.volume);
  fs::path output = settings.output;
  if (output.empty()) {
    const fs::path input(settings.volume);
    output = input.parent_path() / (input.stem().string() + "_integral.npy");
  }
  // From the light that arrived before the window (<stem>_before.exr), as a continuous render's bins are.
  const std::optional<Bitmap> before = readBeforeImage(settings.volume, volume.width(), volume.height());
  writeRunningIntegral(volume, settings.volume, output, before ? &*before : nullptr);
  // Same window and pixels: the sidecar lets plots and `femto compare` use it.
  if (std::optional<VolumeInfo> info = readVolumeInfo(settings.volume)) writeVolumeInfo(volumeInfoPath(output), *info);
  std::cout << "wrote " << output.string() << " (running integral over " << volume.bins() << " bins"
            << (before ? ", from the light before the window" : "") << ")\n";
  return 0;
}

}  // namespace

Command addIntegrateCommand(CLI::App& app) {
  auto settings = std::make_shared<IntegrateSettings>();
  CLI::App* command = app.add_subcommand(
      "integrate", "Write the running integral over time of a transient volume (continuous emission), as .npy");
  addVolumeArgument(*command, settings->volume);
  addOutputOption(*command, settings->output, "Output volume (default: <volume stem>_integral.npy)");
  return [settings] { return integrate(*settings); };
}

}  // namespace femto::cli
