#pragma once
// Which pixels of an image (or of a volume's frames) a comparison counts: an
// optional crop rectangle and an optional mask image (a pixel is included if
// any channel of the mask is nonzero), both given in image pixels.
#include <optional>
#include <string>
#include <vector>

#include <femto/image/image_io.h>

namespace femto {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

/// "x,y,w,h" -> rectangle; an Error naming `option` for anything else.
PixelRect parsePixelRect(const std::string& text, const std::string& option);

class PixelRegion {
 public:
  /// The whole image of `width` x `height`, narrowed by `crop` (must lie
  /// inside the image) and by `mask` (must have the image's size; `maskName`
  /// names it in errors).
  PixelRegion(int width, int height, const std::optional<PixelRect>& crop = std::nullopt,
              const Bitmap* mask = nullptr, const std::string& maskName = "mask");

  /// The crop rectangle (the whole image if none was given).
  const PixelRect& bounds() const { return bounds_; }
  bool contains(int x, int y) const {
    return x >= bounds_.x && y >= bounds_.y && x < bounds_.x + bounds_.width && y < bounds_.y + bounds_.height &&
           (mask_.empty() || mask_[size_t(y) * size_t(width_) + size_t(x)]);
  }
  /// Number of pixels included.
  size_t pixelCount() const { return count_; }

 private:
  int width_;
  PixelRect bounds_;
  std::vector<bool> mask_;  // per image pixel; empty: no mask
  size_t count_ = 0;
};

}  // namespace femto
