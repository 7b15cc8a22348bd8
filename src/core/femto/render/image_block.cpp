#include <femto/render/image_block.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>
#include <femto/core/resources.h>
#include <femto/render/rfilter.h>

namespace femto {
namespace {
constexpr double LargeBlockBytes = 64.0 * 1024 * 1024;
}  // namespace

ImageBlock::ImageBlock(const Point2i& offset, const Point2i& size, const ReconstructionFilter* filter)
    : ImageBlock(offset, size, filter, 3) {}

ImageBlock::ImageBlock(const Point2i& offset, const Point2i& size, const ReconstructionFilter* filter, int channels)
    : offset_(offset), size_(size), filter_(filter), channels_(channels) {
  if (channels < 1) throw Error(str("an image block needs at least one channel, got ", channels));
  // A sample inside the tile reaches pixels whose centres lie within the
  // filter radius: at most ceil(radius - 1/2) pixels beyond the tile's edge.
  border_ = filterBorder(filter);
  // A whole-image block is checked against the free memory before it is
  // allocated (twice: developing it makes an image of the same order);
  // tiles are far below the threshold and skip the check.
  const double bytes = double(storedWidth()) * double(storedHeight()) * double(stride()) * sizeof(float);
  if (bytes > LargeBlockBytes)
    requireMemory(2.0 * bytes, str("the ", size.x, "x", size.y, " image (", channels, " channels)"),
                  "render a smaller image (--resolution WxH) or a crop window");
  data_.assign(size_t(storedWidth()) * storedHeight() * stride(), 0.0f);
}

void ImageBlock::clear() { std::fill(data_.begin(), data_.end(), 0.0f); }

void ImageBlock::unpack(const float* data, size_t count) {
  if (count != data_.size())
    throw Error(str("an image block of ", data_.size(), " floats was sent ", count, " (not the same tile)"));
  std::copy(data, data + count, data_.begin());
}

bool ImageBlock::put(const Point2f& pos, const Color3f& value) {
  if (channels_ != 3) throw Error(str("an RGB sample was put into an image block of ", channels_, " channels"));
  if (!value.isValid()) return false;
  const float rgb[3] = {value.r, value.g, value.b};
  splat(pos, rgb);
  return true;
}

bool ImageBlock::put(const Point2f& pos, const float* values) {
  for (int c = 0; c < channels_; ++c)
    if (!std::isfinite(values[c])) return false;
  splat(pos, values);
  return true;
}

FilterFootprint filterFootprint(const ReconstructionFilter* filter, float px, float py, int width, int height) {
  const float radius = filter ? filter->radius() : 0.5f;
  FilterFootprint f;
  f.x0 = std::max(0, int(std::floor(px - radius)) + 1);
  f.x1 = std::min(width - 1, int(std::floor(px + radius)));
  f.y0 = std::max(0, int(std::floor(py - radius)) + 1);
  f.y1 = std::min(height - 1, int(std::floor(py + radius)));
  if (f.empty()) return f;
  f.x1 = std::min(f.x1, f.x0 + FilterFootprint::Max - 1);
  f.y1 = std::min(f.y1, f.y0 + FilterFootprint::Max - 1);
  for (int x = f.x0; x <= f.x1; ++x) f.wx[x - f.x0] = filter ? filter->evalTabulated(float(x) - px) : 1.0f;
  for (int y = f.y0; y <= f.y1; ++y) f.wy[y - f.y0] = filter ? filter->evalTabulated(float(y) - py) : 1.0f;
  return f;
}

int filterBorder(const ReconstructionFilter* filter) {
  return std::max(0, int(std::ceil((filter ? filter->radius() : 0.5f) - 0.5f)));
}

void ImageBlock::splat(const Point2f& pos, const float* values) {
  // Position relative to the stored area, shifted so pixel i has its centre at i.
  const FilterFootprint f = filterFootprint(filter_, pos.x - float(offset_.x - border_) - 0.5f,
                                            pos.y - float(offset_.y - border_) - 0.5f, storedWidth(), storedHeight());
  if (f.empty()) return;  // outside this block: nothing to add
  for (int y = f.y0; y <= f.y1; ++y) {
    float* row = &data_[(size_t(y) * storedWidth()) * stride()];
    for (int x = f.x0; x <= f.x1; ++x) {
      float w = f.wx[x - f.x0] * f.wy[y - f.y0];
      float* d = row + size_t(x) * stride();
      for (int c = 0; c < channels_; ++c) d[c] += values[c] * w;
      d[channels_] += w;
    }
  }
}

void ImageBlock::merge(const ImageBlock& other) {
  // Film coordinates of the stored areas' corners.
  int ox = other.offset_.x - other.border_, oy = other.offset_.y - other.border_;
  int tx = offset_.x - border_, ty = offset_.y - border_;
  int x0 = std::max(ox, tx), x1 = std::min(ox + other.storedWidth(), tx + storedWidth());
  int y0 = std::max(oy, ty), y1 = std::min(oy + other.storedHeight(), ty + storedHeight());
  if (x0 >= x1) return;
  if (other.channels_ != channels_)
    throw Error(str("cannot merge an image block of ", other.channels_, " channels into one of ", channels_));
  for (int y = y0; y < y1; ++y) {
    const float* src = other.pixel(x0 - ox, y - oy);
    float* dst = &data_[(size_t(y - ty) * storedWidth() + (x0 - tx)) * stride()];
    for (size_t i = 0; i < size_t(x1 - x0) * stride(); ++i) dst[i] += src[i];
  }
}

Color3f ImageBlock::value(const Point2i& p) const {
  if (channels_ != 3) throw Error(str("an RGB value was asked of an image block of ", channels_, " channels"));
  float v[3];
  values(p, v);
  return Color3f(v[0], v[1], v[2]);
}

void ImageBlock::values(const Point2i& p, float* out) const {
  const float* d = pixel(p.x - offset_.x + border_, p.y - offset_.y + border_);
  float inv = d[channels_] == 0.0f ? 0.0f : 1.0f / d[channels_];
  for (int c = 0; c < channels_; ++c) out[c] = d[c] * inv;
}

}  // namespace femto
