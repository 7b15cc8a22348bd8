#pragma once
// Reading colours out of a Bitmap at continuous image coordinates, shared by
// the bitmap texture and the environment map. Conventions (Mitsuba's): uv
// (0, 0) is the top-left corner of the image (row 0 is the top row), texel
// (x, y) covers [x, x+1) x [y, y+1) / resolution, so its centre is at
// ((x + 0.5) / width, (y + 0.5) / height).
#include <string>

#include <femto/image/image_io.h>
#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto {

/// What a lookup outside [0, 1) reads.
enum class WrapMode {
  Repeat,  // tile the image
  Mirror,  // tile with every other copy mirrored (no seams)
  Clamp,   // repeat the edge texels
};

/// "repeat" / "mirror" / "clamp" into `mode`; false (mode untouched) for anything else.
bool parseWrapMode(const std::string& name, WrapMode& mode);
const char* wrapModeName(WrapMode mode);

/// Texel index `i` of an axis with `n` texels, folded into [0, n) by `mode`.
int wrapTexelIndex(int i, int n, WrapMode mode);

/// An image converted to three linear channels: 1 or 2 channels (grey,
/// grey + alpha) become grey RGB, 3 or 4 (RGB, RGBA) keep RGB; alpha is
/// dropped. Throws femto::Error for other channel counts.
Bitmap toRGB(const Bitmap& image);

/// Value of texel (x, y) of a 3-channel image, after wrapping.
Color3f texel(const Bitmap& rgb, int x, int y, WrapMode wrapU, WrapMode wrapV);
/// The texel containing uv (nearest-neighbour lookup).
Color3f lookupNearest(const Bitmap& rgb, const Point2f& uv, WrapMode wrapU, WrapMode wrapV);
/// Bilinear interpolation between the four texel centres around uv.
Color3f lookupBilinear(const Bitmap& rgb, const Point2f& uv, WrapMode wrapU, WrapMode wrapV);

}  // namespace femto
