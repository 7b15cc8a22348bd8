// Time stamps burned into frames (view/frame_label.h): the text names the
// bin's centre precisely enough to tell neighbours apart, and drawing touches
// only the label's box in the top-left corner.
#include <gtest/gtest.h>

#include <femto/view/frame_label.h>

namespace femto {
namespace {

TEST(FrameLabel, BinCentresWithEnoughDecimals) {
  TimeGrid grid;
  grid.start = 3.0, grid.binWidth = 0.01, grid.bins = 1024;
  EXPECT_EQ(binLabel(grid, 0), "OPL 3.005");
  EXPECT_EQ(binLabel(grid, 1), "OPL 3.015");
  grid.binWidth = 0.5;
  EXPECT_EQ(binLabel(grid, 2), "OPL 4.25");
  grid.binWidth = 2.0;
  EXPECT_EQ(binLabel(grid, 1), "OPL 6.0");
}

TEST(FrameLabel, DrawsWhiteGlyphsOnABlackBoxInTheCorner) {
  Bitmap image(64, 48, 3);
  for (float& v : image.data) v = 0.5f;
  drawLabel(image, "OPL 1.5");
  // At 48 rows the scale is 1: the box is 7 glyphs x 6 pixels + 1 wide, 9 tall.
  const int boxWidth = 7 * 6 + 1, boxHeight = 9;
  int white = 0, black = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float v = image.pixel(x, y)[0];
      if (x >= boxWidth || y >= boxHeight) {
        ASSERT_EQ(v, 0.5f) << "outside the label at " << x << "," << y;
        continue;
      }
      EXPECT_TRUE(v == 0.0f || v == 1.0f) << x << "," << y;
      (v == 1.0f ? white : black) += 1;
    }
  EXPECT_GT(white, 40);  // the glyphs' pixels
  EXPECT_GT(black, white);
  // "O" at the first glyph cell: its top row is .XXX. (columns 2-4 of the box).
  EXPECT_EQ(image.pixel(1, 1)[0], 0.0f);
  EXPECT_EQ(image.pixel(2, 1)[0], 1.0f);
  EXPECT_EQ(image.pixel(4, 1)[0], 1.0f);
  EXPECT_EQ(image.pixel(5, 1)[0], 0.0f);
}

TEST(FrameLabel, ScalesWithTheImageAndClipsAtItsEdges) {
  Bitmap big(300, 256, 3);
  drawLabel(big, "8");
  // Scale 2: the 8's top row spans glyph columns 1-3, i.e. pixels 2+2..2+7.
  EXPECT_EQ(big.pixel(4, 2)[1], 1.0f);
  EXPECT_EQ(big.pixel(9, 3)[1], 1.0f);
  EXPECT_EQ(big.pixel(2, 2)[1], 0.0f);
  Bitmap tiny(5, 4, 3);
  EXPECT_NO_THROW(drawLabel(tiny, "OPL 12345.678"));  // clipped, never out of bounds
  EXPECT_NO_THROW(drawLabel(tiny, ""));
}

}  // namespace
}  // namespace femto
