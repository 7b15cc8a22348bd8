#pragma once
// Bounded-memory passes over a transient volume (.npy of shape
// (height, width, bins, 3), see docs/transient-film.md): by runs of whole
// pixels (all bins of each), or by batches of whole frames. The volume may be
// far larger than memory; each pass holds at most a fixed budget of it.
#include <cstddef>
#include <functional>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/film/npy_volume.h>

namespace femto {

/// What the viewing tools hold of a volume at a time (per pass).
constexpr size_t VolumeReadBudgetBytes = size_t(32) << 20;

/// Visit every pixel of rows [rowBegin, rowEnd) (all rows by default) in
/// row-major order, in runs of consecutive pixels of one row:
/// `visit(y, x, count, data)`, `data` holding count * bins * 3 floats in the
/// file's layout. A run holds at most `budgetBytes` (but at least one pixel).
void forEachPixelRun(const NpyVolume& volume, size_t budgetBytes,
                     const std::function<void(int y, int x, int count, const float* data)>& visit,
                     int rowBegin = 0, int rowEnd = -1);

/// How many whole frames (width * height * 3 floats each) fit in
/// `budgetBytes`: at least 1, at most the number of bins.
int framesPerBatch(const NpyVolume& volume, size_t budgetBytes);

/// Frames [bin, bin + count) as RGB images (width x height), one pread per
/// pixel for the whole run of bins.
std::vector<Bitmap> readFrames(const NpyVolume& volume, int bin, int count);

}  // namespace femto
