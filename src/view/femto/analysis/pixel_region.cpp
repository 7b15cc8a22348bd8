#include <femto/analysis/pixel_region.h>

#include <charconv>

#include <femto/base/error.h>

namespace femto {

PixelRect parsePixelRect(const std::string& text, const std::string& option) {
  int v[4];
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int i = 0; i < 4; ++i) {
    auto [next, ec] = std::from_chars(p, end, v[i]);
    bool separatorOk = i < 3 ? next < end && *next == ',' : next == end;
    if (ec != std::errc() || !separatorOk)
      throw Error(str(option, " expects x,y,width,height (whole numbers), got \"", text, "\""));
    p = next + 1;
  }
  if (v[0] < 0 || v[1] < 0 || v[2] <= 0 || v[3] <= 0)
    throw Error(str(option, " expects x,y >= 0 and width,height >= 1, got \"", text, "\""));
  return {v[0], v[1], v[2], v[3]};
}

PixelRegion::PixelRegion(int width, int height, const std::optional<PixelRect>& crop, const Bitmap* mask,
                         const std::string& maskName)
    : width_(width), bounds_{0, 0, width, height} {
  if (crop) {
    if (crop->x + crop->width > width || crop->y + crop->height > height)
      throw Error(str("the crop ", crop->x, ",", crop->y, ",", crop->width, ",", crop->height, " reaches outside the ",
                      width, "x", height, " image"));
    bounds_ = *crop;
  }
  if (mask) {
    if (mask->width != width || mask->height != height)
      throw Error(str("the mask \"", maskName, "\" is ", mask->width, "x", mask->height, ", the images are ", width,
                      "x", height));
    mask_.assign(size_t(width) * size_t(height), false);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < mask->channels; ++c)
          if (mask->pixel(x, y)[c] != 0.0f) mask_[size_t(y) * size_t(width) + size_t(x)] = true;
  }
  for (int y = bounds_.y; y < bounds_.y + bounds_.height; ++y)
    for (int x = bounds_.x; x < bounds_.x + bounds_.width; ++x) count_ += contains(x, y);
}

}  // namespace femto
