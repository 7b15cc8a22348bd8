#include <femto/view/streak.h>

#include <algorithm>

#include <femto/core/error.h>
#include <femto/view/volume_scan.h>

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

}  // namespace femto
