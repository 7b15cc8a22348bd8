#include <femto/view/display.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <femto/view/exposure.h>

namespace femto {
namespace {

struct RampPoint {
  float t;
  Color3f srgb;
};
// Chosen by hand for femto: dark violet to pale yellow through red, each
// step brighter than the last (luma 0.00, 0.10, 0.24, 0.41, 0.66, 0.97).
constexpr std::array<RampPoint, 6> Ramp = {{
    {0.0f, {0.00f, 0.00f, 0.02f}},
    {0.2f, {0.20f, 0.04f, 0.38f}},
    {0.4f, {0.53f, 0.13f, 0.42f}},
    {0.6f, {0.85f, 0.30f, 0.25f}},
    {0.8f, {0.98f, 0.62f, 0.05f}},
    {1.0f, {0.98f, 0.99f, 0.75f}},
}};

}  // namespace

Color3f falseColourRamp(float t) {
  t = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f);
  size_t i = 1;
  while (i + 1 < Ramp.size() && t > Ramp[i].t) ++i;
  const float f = (t - Ramp[i - 1].t) / (Ramp[i].t - Ramp[i - 1].t);
  return Ramp[i - 1].srgb * (1.0f - f) + Ramp[i].srgb * f;
}

Bitmap displayImage(const Bitmap& linear, float exposure, bool falseColour) {
  const float scale = std::exp2(exposure);
  Bitmap out = linear;
  if (!falseColour) {
    for (float& v : out.data) v *= scale;
    return out;
  }
  out = Bitmap(linear.width, linear.height, 3);
  for (int y = 0; y < linear.height; ++y)
    for (int x = 0; x < linear.width; ++x) {
      const float* in = linear.pixel(x, y);
      const float lum = linear.channels >= 3 ? luminanceOf(in) : in[0];
      const Color3f srgb = falseColourRamp(linearToSRGB(std::clamp(lum * scale, 0.0f, 1.0f)));
      // writePNG encodes linear values as sRGB: hand it the ramp's linear colour.
      float* o = out.pixel(x, y);
      for (int c = 0; c < 3; ++c) o[c] = srgbToLinear(srgb[c]);
    }
  return out;
}

}  // namespace femto
