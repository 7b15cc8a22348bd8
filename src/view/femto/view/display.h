#pragma once
// Turning linear radiance into what a PNG shows: a fixed exposure, then
// either the sRGB encoding of the colours (grey-scale brightness as a camera
// would record it) or a false-colour ramp of the luminance.
#include <femto/image/image_io.h>
#include <femto/math/spectrum.h>

namespace femto {

/// The false-colour ramp at t in [0, 1] (clamped), as an sRGB-encoded colour:
/// black, violet, crimson, orange, pale yellow ("inferno"-like). femto's own
/// control points, interpolated linearly in sRGB; their Rec. 709 luma rises
/// monotonically and almost linearly from 0 to 0.97, so brightness order
/// survives a grey-scale print and colour-blind viewing.
Color3f falseColourRamp(float t);

/// `linear` scaled by 2^exposure, ready for writePNG(path, image) with
/// exposure 0. `falseColour`: each pixel becomes the ramp at the sRGB
/// encoding of its exposed luminance (so it is as bright as the grey image).
Bitmap displayImage(const Bitmap& linear, float exposure, bool falseColour);

}  // namespace femto
