// `femto streak out.npy --row Y` (or `--column X`): the x-t slice of a
// transient volume at one image row (a streak image), or the y-t slice at one
// column, as a float EXR and an exposed PNG.
#include <filesystem>
#include <iostream>
#include <memory>

#include <femto/base/error.h>
#include <femto/film/npy_volume.h>
#include <femto/view/display.h>
#include <femto/view/streak.h>

#include "command_options.h"
#include "commands.h"
#include "view_options.h"

namespace fs = std::filesystem;

namespace femto::cli {
namespace {

struct StreakSettings {
  std::string volume;
  std::string output;
  int row = -1, column = -1;
  ExposureSettings exposure;
};

int writeStreak(const StreakSettings& settings) {
  const NpyVolume volume = NpyVolume::open(settings.volume);
  const bool byColumn = settings.column >= 0;
  if (!byColumn && settings.row >= volume.height())
    throw Error(str("--row ", settings.row, " is outside the volume, whose rows are 0 to ", volume.height() - 1));
  if (byColumn && settings.column >= volume.width())
    throw Error(str("--column ", settings.column, " is outside the volume, whose columns are 0 to ",
                    volume.width() - 1));
  const Bitmap streak = byColumn ? streakImageColumn(volume, settings.column) : streakImage(volume, settings.row);
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
    stem = input.parent_path() / (byColumn ? str(input.stem().string(), "_streak_col", settings.column)
                                           : str(input.stem().string(), "_streak_row", settings.row));
  }
  const fs::path exr = fs::path(stem).concat(".exr"), png = fs::path(stem).concat(".png");
  writeEXR(exr, streak);
  writePNG(png, displayImage(streak, exposure, settings.exposure.falseColour));
  std::cout << "wrote " << exr.string() << " and " << png.string() << " (" << streak.width << " x " << streak.height
            << (byColumn ? ": time bins across, y down)\n" : ": x across, time bins down)\n");
  return 0;
}

}  // namespace

Command addStreakCommand(CLI::App& app) {
  auto settings = std::make_shared<StreakSettings>();
  CLI::App* command = app.add_subcommand(
      "streak", "Write the x-t slice (streak image) of a transient volume at one row, or the y-t slice at one column");
  addVolumeArgument(*command, settings->volume);
  CLI::Option* row = command->add_option("--row", settings->row, "Image row Y (0 = top): x across, time down")
                          ->type_name("Y")
                          ->check(CLI::NonNegativeNumber);
  CLI::Option* column = command->add_option("--column", settings->column, "Image column X (0 = left): time across, y down")
                            ->type_name("X")
                            ->check(CLI::NonNegativeNumber)
                            ->excludes(row);
  // Exactly one slice: a usage error (exit 2) like any other bad argument.
  command->parse_complete_callback([row, column] {
    if (row->count() + column->count() == 0) throw CLI::RequiredError("--row Y or --column X");
  });
  addOutputOption(*command, settings->output,
                  "Output stem: writes STEM.exr and STEM.png (default: <volume stem>_streak_row<Y> or _col<X>)",
                  "STEM");
  addExposureOptions(*command, settings->exposure);
  return [settings] { return writeStreak(*settings); };
}

}  // namespace femto::cli
