#include <femto/view/streak.h>

#include <algorithm>
#include <vector>

#include <femto/base/error.h>
#include <femto/film/volume_scan.h>

namespace femto {

Bitmap streakImage(const NpyVolume& volume, int row) {
  const int w = volume.width(), bins = volume.bins();
  if (row < 0 || row >= volume.height())
    throw Error(str("row ", row, " is outside the volume (rows 0 to ", volume.height() - 1, ")"));
  Bitmap streak(w, bins, 3);
  const size_t pixelFloats = size_t(bins) * 3;
  forEachPixelRun(
      volume, VolumeReadBudgetBytes,
      [&](int, int x0, int count, const float* data) {
        for (int p = 0; p < count; ++p)
          for (int b = 0; b < bins; ++b) std::copy_n(data + size_t(p) * pixelFloats + size_t(b) * 3, 3, streak.pixel(x0 + p, b));
      },
      row, row + 1);
  return streak;
}

Bitmap streakImageColumn(const NpyVolume& volume, int column) {
  const int h = volume.height(), bins = volume.bins();
  if (column < 0 || column >= volume.width())
    throw Error(str("column ", column, " is outside the volume (columns 0 to ", volume.width() - 1, ")"));
  Bitmap streak(bins, h, 3);
  std::vector<float> pixel(size_t(bins) * 3);
  for (int y = 0; y < h; ++y) {
    volume.readPixels(y, column, 1, pixel.data());
    for (int b = 0; b < bins; ++b) std::copy_n(&pixel[size_t(b) * 3], 3, streak.pixel(b, y));
  }
  return streak;
}

}  // namespace femto
