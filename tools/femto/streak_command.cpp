// `femto streak out.npy --row Y`: the x-t slice of a transient volume at one
// image row (a streak image), as a float EXR and an exposed PNG.
#include <filesystem>
#include <iostream>
#include <memory>

#include <femto/core/error.h>
#include <femto/render/npy_volume.h>
#include <femto/view/display.h>
#include <femto/view/streak.h>

#include "commands.h"
#include "view_options.h"

namespace fs = std::filesystem;

namespace femto::cli {
namespace {

struct StreakSettings {
  std::string volume;
  std::string output;
  int row = 0;
  ExposureSettings exposure;
};

int writeStreak(const StreakSettings& settings) {
  const NpyVolume volume = NpyVolume::open(settings.volume);
  if (settings.row < 0 || settings.row >= volume.height())
    throw Error(str("--row ", settings.row, " is outside the volume, whose rows are 0 to ", volume.height() - 1));
  const Bitmap streak = streakImage(volume, settings.row);
  // By default exposed for the slice itself; --exposure (e.g. the one
  // `femto frames` printed) makes it match the frames.
  const float exposure = resolveExposure(settings.exposure, [&] {
    LuminanceHistogram histogram;
    for (int y = 0; y < streak.height; ++y)
      for (int x = 0; x < streak.width; ++x) histogram.add(luminanceOf(streak.pixel(x, y)));
    return histogram;
  });
  fs::path stem = settings.output;
  if (stem.empty()) {
    const fs::path input(settings.volume);
    stem = input.parent_path() / str(input.stem().string(), "_streak_row", settings.row);
  }
  const fs::path exr = fs::path(stem).concat(".exr"), png = fs::path(stem).concat(".png");
  writeEXR(exr, streak);
  writePNG(png, displayImage(streak, exposure, settings.exposure.falseColour));
  std::cout << "wrote " << exr.string() << " and " << png.string() << " (" << streak.width << " x " << streak.height
            << ": x across, time bins down)\n";
  return 0;
}

}  // namespace

Command addStreakCommand(CLI::App& app) {
  auto settings = std::make_shared<StreakSettings>();
  CLI::App* command = app.add_subcommand("streak", "Write the x-t slice (streak image) of a transient volume at one row");
  command->add_option("volume", settings->volume, "Transient volume written by a transient film (out.npy)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--row", settings->row, "Image row Y (0 = top)")->type_name("Y")->required();
  command->add_option("-o,--output", settings->output,
                      "Output stem: writes STEM.exr and STEM.png (default: <volume stem>_streak_row<Y>)")
      ->type_name("STEM");
  addExposureOptions(*command, settings->exposure);
  return [settings] { return writeStreak(*settings); };
}

}  // namespace femto::cli
