#include <femto/view/contact_sheet.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>

namespace femto {

ContactSheet::ContactSheet(int tileWidth, int tileHeight, int count, int columns, int gutter)
    : tileWidth_(tileWidth), tileHeight_(tileHeight), count_(count), columns_(std::max(1, std::min(columns, count))),
      gutter_(gutter) {
  const int rows = (count + columns_ - 1) / columns_;
  sheet_ = Bitmap(columns_ * tileWidth + (columns_ - 1) * gutter, std::max(rows, 1) * tileHeight + std::max(rows - 1, 0) * gutter, 3);
}

void ContactSheet::place(int index, const Bitmap& tile) {
  if (index < 0 || index >= count_ || tile.width != tileWidth_ || tile.height != tileHeight_ || tile.channels != 3)
    throw Error(str("contact sheet: tile ", index, " does not fit"));
  const int x0 = (index % columns_) * (tileWidth_ + gutter_), y0 = (index / columns_) * (tileHeight_ + gutter_);
  for (int y = 0; y < tileHeight_; ++y) std::copy_n(tile.pixel(0, y), size_t(tileWidth_) * 3, sheet_.pixel(x0, y0 + y));
}

std::vector<int> sheetFrames(int frameCount, int sheetCount) {
  std::vector<int> frames;
  const int n = std::min(frameCount, sheetCount);
  for (int i = 0; i < n; ++i)
    frames.push_back(n == 1 ? 0 : int(std::lround(double(i) * (frameCount - 1) / (n - 1))));
  return frames;
}

}  // namespace femto
