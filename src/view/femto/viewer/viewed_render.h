#pragma once
// One render `femto view` shows: a transient volume named on the command
// line, with its time axis from the sidecar <stem>.json when there is one.
// Everything is read on request, so opening costs a header read and a memory
// map whatever the volume's size; only the whole-volume answers (the steady
// image, the exposure percentile) read more, once, and are kept.
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <femto/film/mapped_volume.h>
#include <femto/film/npy_volume.h>
#include <femto/image/image_io.h>
#include <femto/time/time_grid.h>
#include <femto/view/exposure.h>

namespace femto {

class ViewedRender {
 public:
  /// Open `volume` (an error names it if it is not a transient volume).
  explicit ViewedRender(const std::filesystem::path& volume);

  /// The file's name, as the page labels it (never its folder).
  const std::string& name() const { return name_; }
  int width() const { return mapped_.width(); }
  int height() const { return mapped_.height(); }
  int bins() const { return mapped_.bins(); }
  /// The time window from the sidecar, if it has one that matches the volume.
  const std::optional<TimeGrid>& timeAxis() const { return timeAxis_; }

  /// Bin `bin` of every pixel: height * width RGB floats, row-major.
  std::vector<float> frame(int bin) const { return mapped_.frame(bin); }
  /// Every bin of pixel (x, y): bins RGB floats.
  std::vector<float> profile(int x, int y) const;
  /// The x-t slice at `row` (width x bins) or y-t slice at `column` (bins x height), as femto streak.
  Bitmap streakRow(int row) const;
  Bitmap streakColumn(int column) const;
  /// The sum over all bins (the time integral over the window, in radiance x
  /// bin units): height * width RGB floats. Reads the whole volume once.
  const std::vector<float>& steady() const;
  /// The luminance below which `percent` % of the non-black voxels lie
  /// (exposure.h), over every bin of a regular grid of pixels: every
  /// `percentileStride()`-th pixel in x and y, few enough to read at most
  /// VolumeReadBudgetBytes, so that it stays quick on a volume of any size
  /// (stride 1, all voxels, for volumes up to that size).
  float percentileLuminance(double percent) const;
  int percentileStride() const;
  /// The bin with the most light (summed luminance) over the same grid of
  /// pixels as percentileLuminance: where the page opens. The first such bin
  /// on ties; 0 for an all-black volume.
  int brightestBin() const;

 private:
  std::string name_;
  NpyVolume volume_;     // pread in runs of whole pixels: streaks (streak.h), the steady sum, the histogram
  MappedVolume mapped_;  // strided and small reads: frames, profiles
  std::optional<TimeGrid> timeAxis_;
  mutable std::once_flag steadyOnce_, histogramOnce_;
  mutable std::vector<float> steady_;
  mutable LuminanceHistogram histogram_;
  mutable std::vector<double> binLight_;  // summed luminance per bin, over the percentile grid
  void sampleGrid() const;
};

}  // namespace femto
