#pragma once
// A rectangle of the film that accumulates filtered samples: per pixel the
// weighted sums of its channels (RGB by default; arbitrary output variables
// use more) and the weight sum (the image is sum / weight). A block
// covers its tile plus a border of the filter radius, so blocks overlap and
// are merged into the full-image block in a fixed order (deterministic sums).
#include <cstdint>
#include <vector>

#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto {

class ReconstructionFilter;

/// The pixels a sample reaches through a reconstruction filter, and their
/// separable weights: for a position (px, py) in a stored area whose pixel i
/// has its centre at i, the pixels with centre offset in (-radius, radius]
/// (half-open, so the box of radius 1/2 gives every position exactly one
/// pixel), clipped to [0, width) x [0, height). ImageBlock and the transient
/// film's tiles splat with it.
struct FilterFootprint {
  static constexpr int Max = 64;
  int x0 = 0, x1 = -1, y0 = 0, y1 = -1;
  float wx[Max], wy[Max];
  bool empty() const { return x0 > x1 || y0 > y1; }
};
/// `filter` null: the box of radius 1/2 (weight 1).
FilterFootprint filterFootprint(const ReconstructionFilter* filter, float px, float py, int width, int height);
/// Pixels a filter reaches beyond the one a sample falls in: ceil(radius - 1/2).
int filterBorder(const ReconstructionFilter* filter);

class ImageBlock {
 public:
  /// `offset`/`size` of the tile in film pixels; `filter` may be null (box of radius 0.5).
  ImageBlock(const Point2i& offset, const Point2i& size, const ReconstructionFilter* filter);
  /// A block of `channels` values per pixel (the RGB put/value below need 3).
  ImageBlock(const Point2i& offset, const Point2i& size, const ReconstructionFilter* filter, int channels);

  /// Splat a sample at continuous film position `pos` (pixel (x, y) covers
  /// [x, x+1) x [y, y+1)). Returns false (and adds nothing) when `value` is
  /// NaN, infinite or negative; the caller counts and reports those.
  bool put(const Point2f& pos, const Color3f& value);
  /// Splat channelCount() values (any sign: positions, normals); returns
  /// false (and adds nothing) when one is NaN or infinite.
  bool put(const Point2f& pos, const float* values);
  /// Add another block's sums into this one where they overlap.
  void merge(const ImageBlock& other);
  void clear();
  /// The stored sums as floats (to send the block to another process), and
  /// back into a block of the same offset, size, filter and channels.
  void pack(std::vector<float>& out) const { out = data_; }
  void unpack(const float* data, size_t count);

  const Point2i& offset() const { return offset_; }
  const Point2i& size() const { return size_; }
  int border() const { return border_; }
  /// Stored extent including the border.
  int storedWidth() const { return size_.x + 2 * border_; }
  int storedHeight() const { return size_.y + 2 * border_; }
  int channelCount() const { return channels_; }
  /// Weighted channel sums then the weight of stored pixel (x, y) (border-relative: 0 is offset - border).
  const float* pixel(int x, int y) const { return &data_[(size_t(y) * storedWidth() + x) * stride()]; }
  /// Developed colour (sum / weight, 0 when weight is 0) of film pixel `p` inside the tile.
  Color3f value(const Point2i& p) const;
  /// Developed values of all channels of film pixel `p` into `out`.
  void values(const Point2i& p, float* out) const;

 private:
  Point2i offset_, size_;
  int border_ = 0;
  size_t stride() const { return size_t(channels_) + 1; }
  void splat(const Point2f& pos, const float* values);

  const ReconstructionFilter* filter_;
  int channels_ = 3;
  std::vector<float> data_;  // channels then weight, per stored pixel
};

}  // namespace femto
