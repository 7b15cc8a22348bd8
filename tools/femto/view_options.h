#pragma once
// Options shared by the commands that look at a transient volume (frames,
// streak, profile): how to expose it, which bins and pixels to show.
#include <functional>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include <femto/math/vector.h>
#include <femto/view/exposure.h>

namespace femto::cli {

/// `--exposure E` (stops) or `--percentile P` (default 99.5) and `--false-colour`.
struct ExposureSettings {
  float exposure = 0.0f;
  double percentile = 99.5;
  bool falseColour = false;
  CLI::Option* exposureOption = nullptr;  // count() > 0 when --exposure was given
};
void addExposureOptions(CLI::App& command, ExposureSettings& settings);

/// The given exposure, or the one that maps the percentile of `luminances()`
/// to white; prints which, so that another command can reuse it with --exposure.
float resolveExposure(const ExposureSettings& settings, const std::function<LuminanceHistogram()>& luminances);

/// "a:b" (either side may be empty: 0 and `bins`) -> [a, b) within [0, bins].
std::pair<int, int> parseBinRange(const std::string& text, int bins);
/// "x,y" -> a pixel inside width x height.
Point2i parsePixel(const std::string& text, int width, int height);

}  // namespace femto::cli
