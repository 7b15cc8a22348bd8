#include <femto/image/texel_lookup.h>

#include <algorithm>
#include <cmath>

#include <femto/base/error.h>

namespace femto {
namespace {

/// floor(v) as an int, with NaN and far-away coordinates (a wild to_uv scale)
/// pinned to a representable range instead of undefined behaviour.
int floorToIndex(float v) {
  constexpr float limit = 1 << 30;
  if (!(v > -limit)) return -(1 << 30);
  if (!(v < limit)) return 1 << 30;
  return int(std::floor(v));
}

}  // namespace

bool parseWrapMode(const std::string& name, WrapMode& mode) {
  if (name == "repeat") mode = WrapMode::Repeat;
  else if (name == "mirror") mode = WrapMode::Mirror;
  else if (name == "clamp") mode = WrapMode::Clamp;
  else return false;
  return true;
}

const char* wrapModeName(WrapMode mode) {
  switch (mode) {
    case WrapMode::Repeat: return "repeat";
    case WrapMode::Mirror: return "mirror";
    case WrapMode::Clamp: return "clamp";
  }
  return "?";
}

int wrapTexelIndex(int i, int n, WrapMode mode) {
  switch (mode) {
    case WrapMode::Repeat: {
      int r = i % n;
      return r < 0 ? r + n : r;
    }
    case WrapMode::Mirror: {
      // Period 2n: 0..n-1 forward, then n-1..0 backward.
      int r = i % (2 * n);
      if (r < 0) r += 2 * n;
      return r < n ? r : 2 * n - 1 - r;
    }
    case WrapMode::Clamp: return std::clamp(i, 0, n - 1);
  }
  return 0;
}

Bitmap toRGB(const Bitmap& image) {
  if (image.channels < 1 || image.channels > 4)
    throw Error(str("images with ", image.channels, " channels are not supported (1 to 4: grey, grey+alpha, RGB, RGBA)"));
  Bitmap rgb(image.width, image.height, 3);
  bool grey = image.channels < 3;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* in = image.pixel(x, y);
      float* out = rgb.pixel(x, y);
      for (int c = 0; c < 3; ++c) out[c] = grey ? in[0] : in[c];
    }
  return rgb;
}

Color3f texel(const Bitmap& rgb, int x, int y, WrapMode wrapU, WrapMode wrapV) {
  const float* p = rgb.pixel(wrapTexelIndex(x, rgb.width, wrapU), wrapTexelIndex(y, rgb.height, wrapV));
  return {p[0], p[1], p[2]};
}

Color3f lookupNearest(const Bitmap& rgb, const Point2f& uv, WrapMode wrapU, WrapMode wrapV) {
  return texel(rgb, floorToIndex(uv.x * float(rgb.width)), floorToIndex(uv.y * float(rgb.height)), wrapU, wrapV);
}

Color3f lookupBilinear(const Bitmap& rgb, const Point2f& uv, WrapMode wrapU, WrapMode wrapV) {
  // Shift by half a texel so integer positions are texel centres.
  float x = uv.x * float(rgb.width) - 0.5f, y = uv.y * float(rgb.height) - 0.5f;
  int ix = floorToIndex(x), iy = floorToIndex(y);
  float fx = std::clamp(x - float(ix), 0.0f, 1.0f), fy = std::clamp(y - float(iy), 0.0f, 1.0f);
  return texel(rgb, ix, iy, wrapU, wrapV) * ((1.0f - fx) * (1.0f - fy)) +
         texel(rgb, ix + 1, iy, wrapU, wrapV) * (fx * (1.0f - fy)) +
         texel(rgb, ix, iy + 1, wrapU, wrapV) * ((1.0f - fx) * fy) +
         texel(rgb, ix + 1, iy + 1, wrapU, wrapV) * (fx * fy);
}

}  // namespace femto
