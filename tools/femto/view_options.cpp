#include "view_options.h"

#include "arguments.h"

#include <charconv>
#include <iomanip>
#include <iostream>
#include <string_view>

#include <femto/base/error.h>

namespace femto::cli {
namespace {

bool parseInt(std::string_view text, int& value) {
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

void addExposureOptions(CLI::App& command, ExposureSettings& settings) {
  settings.exposureOption =
      command.add_option("--exposure", settings.exposure, "Exposure in stops (scale 2^E) for every image")->type_name("E");
  command
      .add_option("--percentile", settings.percentile,
                  "Map this percentile of all non-black voxels' luminance to white (default 99.5)")
      ->type_name("P")
      ->check(CLI::Range(0.0, 100.0))
      ->excludes(settings.exposureOption);
  command.add_flag("--false-colour,--false-color", settings.falseColour,
                   "Show luminance with a perceptual false-colour ramp instead of grey-scale colours");
}

float resolveExposure(const ExposureSettings& settings, const std::function<LuminanceHistogram()>& luminances) {
  if (settings.exposureOption->count() > 0) return settings.exposure;
  const LuminanceHistogram histogram = luminances();
  const float white = histogram.percentile(settings.percentile);
  const float exposure = exposureForWhite(white);
  if (histogram.count() == 0)
    std::cout << "the volume is black; exposure 0\n";
  else
    std::cout << "exposure " << std::setprecision(4) << exposure << " stops (percentile " << settings.percentile
              << " of luminance: " << white << ")\n";
  return exposure;
}

std::pair<int, int> parseBinRange(const std::string& text, int bins) {
  if (text.empty()) return {0, bins};
  const size_t colon = text.find(':');
  int a = 0, b = bins;
  const std::string_view view(text);
  const bool ok = colon != std::string::npos && (colon == 0 || parseInt(view.substr(0, colon), a)) &&
                  (colon + 1 == text.size() || parseInt(view.substr(colon + 1), b));
  if (!ok) throw Error(str("--bins expects FIRST:END (bins FIRST to END-1; either may be left out), got \"", text, "\""));
  if (a < 0 || b > bins || a >= b)
    throw Error(str("--bins ", text, " selects no bins of the volume's ", bins, " (0:", bins, ")"));
  return {a, b};
}

Point2i parsePixel(const std::string& text, int width, int height) {
  const size_t comma = text.find(',');
  int x = 0, y = 0;
  if (comma == std::string::npos || !parseInt(std::string_view(text).substr(0, comma), x) ||
      !parseInt(std::string_view(text).substr(comma + 1), y))
    throw UsageError(str("--pixel expects X,Y (column, row), got \"", text, "\""));
  if (x < 0 || x >= width || y < 0 || y >= height)
    throw Error(str("--pixel ", text, " is outside the volume (", width, "x", height, ")"));
  return Point2i(x, y);
}

}  // namespace femto::cli
