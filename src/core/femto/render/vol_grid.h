#pragma once
// Mitsuba's binary .vol grid file (Mitsuba 0.6 GridDataSource, also read by
// Mitsuba 3): bytes 'V','O','L', version byte 3; int32 encoding (1 =
// float32, the only one supported); int32 xres, yres, zres; int32 channels;
// six float32 giving the bounding box (xmin ymin zmin xmax ymax zmax); then
// xres*yres*zres*channels float32 values, x fastest:
// value[((z * yres + y) * xres + x) * channels + c]. Read by the gridvolume
// volume and the sdfgrid shape.
#include <array>
#include <functional>
#include <string>
#include <vector>

#include <femto/math/bbox.h>

namespace femto {

struct VolGrid {
  std::array<int, 3> res{1, 1, 1};
  int channels = 1;
  BoundingBox3f box;
  std::vector<float> data;
  size_t voxels() const { return size_t(res[0]) * size_t(res[1]) * size_t(res[2]); }
};

/// Read `filename`; `fail(why)` is called (and must throw) for a file that
/// cannot be read, is not a .vol, or holds anything but finite float32
/// values with 1 or 3 channels.
VolGrid readVolGrid(const std::string& filename, const std::function<void(const std::string&)>& fail);

}  // namespace femto
