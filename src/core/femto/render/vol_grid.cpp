#include <femto/render/vol_grid.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>

#include <femto/base/error.h>

namespace femto {

VolGrid readVolGrid(const std::string& filename, const std::function<void(const std::string&)>& fail) {
  VolGrid g;
  std::ifstream in(filename, std::ios::binary);
  if (!in) fail("cannot open it");
  char magic[4];
  int32_t header[5];
  float bounds[6];
  if (!in.read(magic, 4)) fail("too short for a .vol header");
  if (std::memcmp(magic, "VOL", 3) != 0) fail("not a Mitsuba .vol file (it does not start with \"VOL\")");
  if (magic[3] != 3) fail(str("unsupported .vol version ", int(magic[3]), " (expected 3)"));
  if (!in.read(reinterpret_cast<char*>(header), sizeof header) || !in.read(reinterpret_cast<char*>(bounds), sizeof bounds))
    fail("too short for a .vol header");
  if (header[0] != 1) fail(str("unsupported encoding ", header[0], " (only 1 = float32 is supported)"));
  for (int a = 0; a < 3; ++a) {
    g.res[a] = header[1 + a];
    if (g.res[a] < 1 || g.res[a] > 65536) fail(str("bad resolution ", header[1], "x", header[2], "x", header[3]));
  }
  g.channels = header[4];
  if (g.channels != 1 && g.channels != 3) fail(str("has ", g.channels, " channels; only 1 or 3 are supported"));
  g.box = BoundingBox3f(Point3f(bounds[0], bounds[1], bounds[2]), Point3f(bounds[3], bounds[4], bounds[5]));
  for (float b : bounds)
    if (!std::isfinite(b)) fail("bounding box is not finite");
  const size_t count = g.voxels() * size_t(g.channels);
  g.data.resize(count);
  if (!in.read(reinterpret_cast<char*>(g.data.data()), std::streamsize(count * sizeof(float))))
    fail(str("truncated: expected ", count, " float32 values after the header"));
  for (float v : g.data)
    if (!std::isfinite(v)) fail("contains a value that is not finite");
  return g;
}

}  // namespace femto
