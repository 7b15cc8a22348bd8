#include <femto/film/volume_scan.h>

#include <algorithm>

#include <femto/base/error.h>

namespace femto {

void forEachPixelRun(const NpyVolume& volume, size_t budgetBytes,
                     const std::function<void(int y, int x, int count, const float* data)>& visit,
                     int rowBegin, int rowEnd) {
  const size_t pixelBytes = size_t(volume.bins()) * 3 * sizeof(float);
  const int run = int(std::clamp<size_t>(budgetBytes / pixelBytes, 1, size_t(std::max(volume.width(), 1))));
  std::vector<float> data(size_t(run) * volume.bins() * 3);
  if (rowEnd < 0) rowEnd = volume.height();
  for (int y = rowBegin; y < rowEnd; ++y)
    for (int x = 0; x < volume.width(); x += run) {
      const int count = std::min(run, volume.width() - x);
      volume.readPixels(y, x, count, data.data());
      visit(y, x, count, data.data());
    }
}

int framesPerBatch(const NpyVolume& volume, size_t budgetBytes) {
  const size_t frameBytes = std::max<size_t>(size_t(volume.width()) * volume.height() * 3 * sizeof(float), 1);
  return int(std::clamp<size_t>(budgetBytes / frameBytes, 1, size_t(std::max(volume.bins(), 1))));
}

std::vector<Bitmap> readFrames(const NpyVolume& volume, int bin, int count) {
  if (bin < 0 || count < 0 || bin + count > volume.bins())
    throw Error(str("frames [", bin, ", ", bin + count, ") are outside the volume's ", volume.bins(), " bins"));
  const int w = volume.width(), h = volume.height();
  std::vector<Bitmap> frames(size_t(count), Bitmap(w, h, 3));
  std::vector<float> run(size_t(count) * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      volume.readBins(y, x, bin, count, run.data());
      for (int k = 0; k < count; ++k) std::copy_n(&run[size_t(k) * 3], 3, frames[size_t(k)].pixel(x, y));
    }
  return frames;
}

}  // namespace femto
