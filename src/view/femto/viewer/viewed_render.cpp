#include <femto/viewer/viewed_render.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>
#include <femto/film/volume_info.h>
#include <femto/film/volume_scan.h>
#include <femto/view/streak.h>

namespace femto {

ViewedRender::ViewedRender(const std::filesystem::path& volume)
    : name_(volume.filename().string()), volume_(NpyVolume::open(volume)), mapped_(MappedVolume::open(volume)) {
  if (std::optional<VolumeInfo> info = readVolumeInfo(volume); info && info->grid.bins == bins())
    timeAxis_ = info->grid;
}

std::vector<float> ViewedRender::profile(int x, int y) const {
  if (x < 0 || x >= width() || y < 0 || y >= height())
    throw Error(str("pixel ", x, ",", y, " is outside the volume (", width(), "x", height(), ")"));
  const float* p = mapped_.pixel(y, x);
  return std::vector<float>(p, p + size_t(bins()) * 3);
}

Bitmap ViewedRender::streakRow(int row) const { return streakImage(volume_, row); }
Bitmap ViewedRender::streakColumn(int column) const { return streakImageColumn(volume_, column); }

const std::vector<float>& ViewedRender::steady() const {
  std::call_once(steadyOnce_, [this] {
    steady_.assign(size_t(width()) * height() * 3, 0.0f);
    const size_t pixelFloats = size_t(bins()) * 3;
    forEachPixelRun(volume_, VolumeReadBudgetBytes, [&](int y, int x0, int count, const float* data) {
      for (int p = 0; p < count; ++p) {
        // Summed in double: thousands of bins of very different sizes.
        double sum[3] = {0.0, 0.0, 0.0};
        for (int b = 0; b < bins(); ++b)
          for (int c = 0; c < 3; ++c) sum[c] += data[size_t(p) * pixelFloats + size_t(b) * 3 + c];
        float* out = &steady_[(size_t(y) * width() + x0 + p) * 3];
        for (int c = 0; c < 3; ++c) out[c] = float(sum[c]);
      }
    });
  });
  return steady_;
}

int ViewedRender::percentileStride() const {
  const double pixelBytes = double(bins()) * 3 * sizeof(float);
  const double pixels = double(width()) * height();
  const double affordable = std::max(1.0, std::floor(double(VolumeReadBudgetBytes) / pixelBytes));
  // Every k-th pixel in x and y reads about pixels / k^2 pixels.
  return std::max(1, int(std::ceil(std::sqrt(pixels / affordable))));
}

void ViewedRender::sampleGrid() const {
  std::call_once(histogramOnce_, [this] {
    const int k = percentileStride();
    std::vector<float> pixel(size_t(bins()) * 3);
    binLight_.assign(size_t(bins()), 0.0);
    for (int y = k / 2; y < height(); y += k)
      for (int x = k / 2; x < width(); x += k) {
        volume_.readPixels(y, x, 1, pixel.data());
        for (int b = 0; b < bins(); ++b) {
          const float luminance = luminanceOf(&pixel[size_t(b) * 3]);
          histogram_.add(luminance);
          if (std::isfinite(luminance)) binLight_[size_t(b)] += luminance;
        }
      }
  });
}

float ViewedRender::percentileLuminance(double percent) const {
  sampleGrid();
  return histogram_.percentile(percent);
}

int ViewedRender::brightestBin() const {
  sampleGrid();
  int best = 0;
  for (int b = 1; b < bins(); ++b)
    if (binLight_[size_t(b)] > binLight_[size_t(best)]) best = b;
  return best;
}

}  // namespace femto
