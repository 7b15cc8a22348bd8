#pragma once
// `femto compare REF TEST`: error metrics of a test rendering against a
// reference, for steady images (EXR or anything OpenImageIO reads) and for
// transient volumes (.npy, streamed from disk a bounded chunk at a time).
// Mismatched inputs (kind, size, channels, time bins, time window, crop) are
// refused with one sentence naming both files. Formulas: docs/compare.md.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <femto/analysis/image_metrics.h>
#include <femto/analysis/pixel_region.h>
#include <femto/time/time_grid.h>

namespace femto {

/// A half-open range of time bins [begin, end); an absent end means "to the
/// last bin", an absent begin "from bin 0".
struct BinRange {
  std::optional<int> begin, end;
};
/// "a:b", "a:" or ":b" (bins, end exclusive); an Error naming `option` otherwise.
BinRange parseBinRange(const std::string& text, const std::string& option);

struct CompareSettings {
  double epsilon = DefaultRelMseEpsilon;
  std::optional<PixelRect> crop;
  std::filesystem::path mask;  // empty: every pixel of the crop
  BinRange bins;               // volumes only
  bool binsGiven = false;
};

struct Comparison {
  std::filesystem::path reference, test;
  bool transient = false;
  int width = 0, height = 0, channels = 0;
  int bins = 0, binBegin = 0, binEnd = 0;  // transient only
  std::optional<TimeGrid> grid;            // the volumes' time window, when their sidecars give it
  size_t pixels = 0;                       // pixels counted (crop and mask applied)
  double epsilon = DefaultRelMseEpsilon;
  /// Image: over pixels x channels. Volume: over pixels x bins of the window x channels.
  ErrorMetrics metrics;
  /// Volume: of the time integral (each pixel's sum over the window's bins), over pixels x channels.
  ErrorMetrics integral;
  /// Volume: one entry per bin of the window, over pixels x channels of that bin.
  std::vector<ErrorMetrics> perBin;
};

/// Compare `test` against `reference`: both .npy volumes or both images.
Comparison compareFiles(const std::filesystem::path& reference, const std::filesystem::path& test,
                        const CompareSettings& settings);

}  // namespace femto
