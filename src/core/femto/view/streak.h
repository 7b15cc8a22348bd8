#pragma once
// The streak image, the classic view of transient renderers and of the streak
// cameras they imitate (Velten et al. 2013, "Femto-photography"): one row of
// the image against time. x runs left to right, time (bins) top to bottom.
#include <femto/image/image_io.h>
#include <femto/render/npy_volume.h>

namespace femto {

/// The x-t slice at image row `row` of `volume`: width x bins RGB; pixel
/// (x, b) is the volume's value (row, x, b). Reads the row in bounded runs.
Bitmap streakImage(const NpyVolume& volume, int row);

}  // namespace femto
