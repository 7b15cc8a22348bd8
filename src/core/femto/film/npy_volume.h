#pragma once
// A NumPy .npy file of float32 (little-endian), C order, shape
// (height, width, bins, 3), written in pieces: the header and the file's full
// size first, then any run of consecutive pixels of one row with pwrite at its
// offset, so a volume far larger than memory can be filled tile by tile.
// Format: https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html
// (version 1.0: magic, 2-byte header length, Python-dict header padded with
// spaces and a newline to a multiple of 64 bytes).
#include <cstdint>
#include <filesystem>
#include <vector>

namespace femto {

class NpyVolume {
 public:
  /// Create (truncate) `path` with a header for shape (height, width, bins, 3),
  /// sized to hold all data (unwritten parts read as zeros).
  static NpyVolume create(const std::filesystem::path& path, int height, int width, int bins);
  /// Open an existing float32 (h, w, bins, 3) C-order volume for reading
  /// (and writing, when `writable`: a volume another process created).
  static NpyVolume open(const std::filesystem::path& path, bool writable = false);
  NpyVolume(NpyVolume&& other) noexcept;
  NpyVolume& operator=(NpyVolume&&) = delete;
  ~NpyVolume();

  int height() const { return height_; }
  int width() const { return width_; }
  int bins() const { return bins_; }
  /// Byte offset of the data (header size).
  uint64_t dataOffset() const { return dataOffset_; }

  /// Write `count` consecutive pixels of row `y` starting at column `x`:
  /// count * bins * 3 floats.
  void writePixels(int y, int x, int count, const float* data);
  /// Read them back (same layout).
  void readPixels(int y, int x, int count, float* data) const;
  /// Read bins [bin, bin + count) of pixel (x, y): count * 3 floats.
  void readBins(int y, int x, int bin, int count, float* data) const;

 private:
  NpyVolume(std::filesystem::path path, int fd, int height, int width, int bins, uint64_t dataOffset);
  uint64_t offsetOf(int y, int x) const;
  std::filesystem::path path_;
  int fd_ = -1;
  int height_ = 0, width_ = 0, bins_ = 0;
  uint64_t dataOffset_ = 0;
};

/// The .npy v1.0 header for a float32 C-order array of `shape`.
std::vector<char> npyHeader(const std::vector<int64_t>& shape);

}  // namespace femto
