#pragma once
// The streak image, the classic view of transient renderers and of the streak
// cameras they imitate (Velten et al. 2013, "Femto-photography"): one row of
// the image against time. x runs left to right, time (bins) top to bottom;
// for one column, y runs top to bottom and time left to right, so the image's
// spatial axis keeps its orientation in both.
#include <femto/image/image_io.h>
#include <femto/film/npy_volume.h>

namespace femto {

/// The x-t slice at image row `row` of `volume`: width x bins RGB; pixel
/// (x, b) is the volume's value (row, x, b). Reads the row in bounded runs.
Bitmap streakImage(const NpyVolume& volume, int row);

/// The y-t slice at image column `column`: bins x height RGB; pixel (b, y) is
/// the volume's value (y, column, b). Reads one pixel's bins per row.
Bitmap streakImageColumn(const NpyVolume& volume, int column);

}  // namespace femto
