#pragma once
// A transient volume (.npy, shape (height, width, bins, 3), see npy_volume.h)
// memory-mapped read-only, for readers that jump about it: a frame is one
// float from every pixel's run of bins, strided bins * 3 floats apart, which
// by pread would take one system call per pixel. Mapping costs nothing up
// front (the kernel pages in only what is touched), so a volume far larger
// than memory opens at once and a frame reads only the pages it touches. For
// passes over whole pixels, volume_scan.h's pread in large runs is faster.
#include <cstddef>
#include <filesystem>
#include <vector>

namespace femto {

class MappedVolume {
 public:
  /// Map `path`, checked as NpyVolume::open checks it (format, shape, size).
  static MappedVolume open(const std::filesystem::path& path);
  MappedVolume(MappedVolume&& other) noexcept;
  MappedVolume& operator=(MappedVolume&&) = delete;
  ~MappedVolume();

  int height() const { return height_; }
  int width() const { return width_; }
  int bins() const { return bins_; }

  /// The bins * 3 floats of pixel (x, y), in the file's layout.
  const float* pixel(int y, int x) const {
    return data_ + (size_t(y) * size_t(width_) + size_t(x)) * size_t(bins_) * 3;
  }
  /// Bin `bin` of every pixel: height * width * 3 floats, row-major, RGB.
  std::vector<float> frame(int bin) const;
  /// Pages of the mapping (header included) in memory now, by mincore(2):
  /// what a reader has touched, the kernel's readahead included.
  size_t residentPages() const;
  /// Pages the mapping spans.
  size_t mappedPages() const;

 private:
  MappedVolume(void* mapping, size_t mappedBytes, const float* data, int height, int width, int bins);
  void* mapping_ = nullptr;
  size_t mappedBytes_ = 0;
  const float* data_ = nullptr;
  int height_ = 0, width_ = 0, bins_ = 0;
};

}  // namespace femto
