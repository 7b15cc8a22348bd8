#pragma once
// Tiny images and transient volumes with known values, for the tests of
// femto compare (unit tests and the CLI tests' input writer).
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/film/npy_volume.h>
#include <femto/film/volume_info.h>

namespace femto::test {

/// value(x, y, channel) for an image, value(x, y, bin, channel) for a volume.
using ImageValue = std::function<float(int, int, int)>;
using VolumeValue = std::function<float(int, int, int, int)>;

inline void writeTestImage(const std::filesystem::path& path, int w, int h, int channels, const ImageValue& value) {
  Bitmap image(w, h, channels);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) image.pixel(x, y)[c] = value(x, y, c);
  writeEXR(path, image);
}

/// A (h, w, bins, 3) volume, with a sidecar for `grid` if one is given.
inline void writeTestVolume(const std::filesystem::path& path, int w, int h, int bins, const VolumeValue& value,
                            std::optional<TimeGrid> grid = std::nullopt) {
  NpyVolume volume = NpyVolume::create(path, h, w, bins);
  std::vector<float> row(size_t(w) * bins * 3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x)
      for (int b = 0; b < bins; ++b)
        for (int c = 0; c < 3; ++c) row[(size_t(x) * bins + b) * 3 + c] = value(x, y, b, c);
    volume.writePixels(y, 0, w, row.data());
  }
  std::filesystem::remove(volumeInfoPath(path));
  if (grid) {
    VolumeInfo info;
    info.width = w, info.height = h, info.grid = *grid;
    info.filmSize = {w, h};
    writeVolumeInfo(volumeInfoPath(path), info);
  }
}

/// OPL window of `bins` bins of width 0.5 from `start`.
inline TimeGrid testGrid(int bins, double start = 1.0) { return TimeGrid{start, 0.5, bins}; }

}  // namespace femto::test
