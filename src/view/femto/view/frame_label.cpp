#include <femto/view/frame_label.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace femto {
namespace {

constexpr int GlyphWidth = 5, GlyphHeight = 7;

/// Rows of a glyph, top first; bit 4 is the leftmost pixel.
using Glyph = std::array<uint8_t, GlyphHeight>;

const Glyph* glyph(char c) {
  static const Glyph digits[10] = {
      {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E},  // 0
      {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E},  // 1
      {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F},  // 2
      {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E},  // 3
      {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02},  // 4
      {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E},  // 5
      {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E},  // 6
      {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08},  // 7
      {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E},  // 8
      {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C},  // 9
  };
  static const Glyph dot = {0, 0, 0, 0, 0, 0x0C, 0x0C}, minus = {0, 0, 0, 0x1F, 0, 0, 0},
                     plus = {0, 0x04, 0x04, 0x1F, 0x04, 0x04, 0}, equals = {0, 0, 0x1F, 0, 0x1F, 0, 0},
                     O = {0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E}, P = {0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10},
                     L = {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F}, b = {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1E},
                     i = {0x04, 0, 0x0C, 0x04, 0x04, 0x04, 0x0E}, n = {0, 0, 0x16, 0x19, 0x11, 0x11, 0x11};
  if (c >= '0' && c <= '9') return &digits[c - '0'];
  switch (c) {
    case '.': return &dot;
    case '-': return &minus;
    case '+': return &plus;
    case '=': return &equals;
    case 'O': return &O;
    case 'P': return &P;
    case 'L': return &L;
    case 'b': return &b;
    case 'i': return &i;
    case 'n': return &n;
    default: return nullptr;  // space and anything else: blank
  }
}

void fill(Bitmap& image, int x0, int y0, int w, int h, float value) {
  for (int y = std::max(y0, 0); y < std::min(y0 + h, image.height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x0 + w, image.width); ++x)
      for (int c = 0; c < std::min(image.channels, 3); ++c) image.pixel(x, y)[c] = value;
}

}  // namespace

std::string binLabel(const TimeGrid& grid, int bin) {
  const double width = grid.binWidth;
  // One decimal more than the bin width needs, so neighbours differ.
  int decimals = width > 0 ? int(std::ceil(-std::log10(width))) + 1 : 3;
  decimals = std::clamp(decimals, 0, 6);
  char text[64];
  std::snprintf(text, sizeof(text), "OPL %.*f", decimals, grid.start + (bin + 0.5) * width);
  return text;
}

void drawLabel(Bitmap& image, const std::string& text) {
  if (text.empty() || image.width <= 0 || image.height <= 0) return;
  const int scale = std::max(1, image.height / 128);
  const int advance = (GlyphWidth + 1) * scale, pad = scale;
  fill(image, 0, 0, int(text.size()) * advance + pad, GlyphHeight * scale + 2 * pad, 0.0f);
  for (size_t k = 0; k < text.size(); ++k) {
    const Glyph* g = glyph(text[k]);
    if (!g) continue;
    for (int row = 0; row < GlyphHeight; ++row)
      for (int col = 0; col < GlyphWidth; ++col)
        if ((*g)[size_t(row)] & (0x10 >> col))
          fill(image, pad + int(k) * advance + col * scale, pad + row * scale, scale, scale, 1.0f);
  }
}

}  // namespace femto
