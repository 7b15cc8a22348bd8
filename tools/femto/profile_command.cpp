// `femto profile out.npy --pixel x,y`: radiance against time at chosen
// pixels, as CSV (for spreadsheets and plotting without Python; see also
// tools/view/plot_profiles.py).
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include <femto/base/error.h>
#include <femto/film/npy_volume.h>
#include <femto/film/volume_info.h>
#include <femto/view/exposure.h>

#include "command_options.h"
#include "commands.h"
#include "view_options.h"

namespace femto::cli {
namespace {

struct ProfileSettings {
  std::string volume;
  std::string output;
  std::vector<std::string> pixels;
};

/// `grid`: the volume's time window from its sidecar, if any (adds the
/// column `opl`, the OPL at each bin's centre).
void writeCsv(std::ostream& out, const NpyVolume& volume, const std::vector<Point2i>& pixels,
              const std::optional<TimeGrid>& grid) {
  std::vector<std::vector<float>> runs;
  out << "bin";
  if (grid) out << ",opl";
  for (const Point2i& p : pixels) {
    runs.emplace_back(size_t(volume.bins()) * 3);
    volume.readBins(p.y, p.x, 0, volume.bins(), runs.back().data());
    for (const char* channel : {"r", "g", "b", "luminance"}) out << ',' << channel << '_' << p.x << '_' << p.y;
  }
  out << '\n';
  out.precision(9);
  for (int b = 0; b < volume.bins(); ++b) {
    out << b;
    if (grid) out << ',' << grid->start + (b + 0.5) * grid->binWidth;
    for (const std::vector<float>& run : runs) {
      const float* v = &run[size_t(b) * 3];
      out << ',' << v[0] << ',' << v[1] << ',' << v[2] << ',' << luminanceOf(v);
    }
    out << '\n';
  }
}

int writeProfiles(const ProfileSettings& settings) {
  const NpyVolume volume = NpyVolume::open(settings.volume);
  std::vector<Point2i> pixels;
  for (const std::string& text : settings.pixels) pixels.push_back(parsePixel(text, volume.width(), volume.height()));
  std::optional<TimeGrid> grid;
  if (std::optional<VolumeInfo> info = readVolumeInfo(settings.volume); info && info->grid.bins == volume.bins())
    grid = info->grid;
  if (settings.output.empty() || settings.output == "-") {
    writeCsv(std::cout, volume, pixels, grid);
    return 0;
  }
  std::ofstream file(settings.output);
  if (!file) throw Error(str("cannot write \"", settings.output, "\""));
  writeCsv(file, volume, pixels, grid);
  if (!file.flush()) throw Error(str("cannot write \"", settings.output, "\""));
  return 0;
}

}  // namespace

Command addProfileCommand(CLI::App& app) {
  auto settings = std::make_shared<ProfileSettings>();
  CLI::App* command =
      app.add_subcommand("profile", "Write radiance against time bin at chosen pixels of a transient volume, as CSV");
  addVolumeArgument(*command, settings->volume);
  command->add_option("--pixel", settings->pixels, "Pixel X,Y (column, row; repeatable)")
      ->type_name("X,Y")
      ->required()
      ->allow_extra_args(false);
  addOutputOption(*command, settings->output, "CSV file (default: standard output)");
  return [settings] { return writeProfiles(*settings); };
}

}  // namespace femto::cli
