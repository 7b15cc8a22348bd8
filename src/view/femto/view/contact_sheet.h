#pragma once
// A contact sheet: equally sized images (frames) tiled left to right, top to
// bottom, in a grid, separated by a black gutter. One picture of a whole
// sequence, for a report or a README.
#include <femto/image/image_io.h>

namespace femto {

class ContactSheet {
 public:
  /// Room for `count` tiles of tileWidth x tileHeight (3 channels) in
  /// `columns` columns, `gutter` pixels apart.
  ContactSheet(int tileWidth, int tileHeight, int count, int columns, int gutter);
  /// Put `tile` (tileWidth x tileHeight, 3 channels) at position `index`.
  void place(int index, const Bitmap& tile);
  const Bitmap& image() const { return sheet_; }

 private:
  int tileWidth_, tileHeight_, count_, columns_, gutter_;
  Bitmap sheet_;
};

/// Which `sheetCount` of `frameCount` frames a sheet shows: evenly spaced,
/// always the first and the last (all of them when sheetCount >= frameCount).
/// Returns frame indices in increasing order.
std::vector<int> sheetFrames(int frameCount, int sheetCount);

}  // namespace femto
