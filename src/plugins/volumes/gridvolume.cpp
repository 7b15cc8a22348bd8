// gridvolume: a regular grid of values read from Mitsuba's binary .vol file,
// interpolated trilinearly.
//
// The file: render/vol_grid.h.
//
// As in Mitsuba 0.6, the samples sit on the grid's vertices: sample (0,0,0)
// at the box's min corner and (xres-1, yres-1, zres-1) at its max corner;
// outside the box the volume is 0. "to_world" places the box in the scene.
// (Mitsuba 3 places grids in the unit cube whatever box the file stores, and
// its samples sit at cell centres: a Mitsuba 3 scene whose file stores a
// different box, or that relies on cell-centred samples, places differently.)
//
// | name     | type      | default  | meaning                                    | unit |
// |----------|-----------|----------|--------------------------------------------|------|
// | filename | string    | required | .vol file (the loader resolves the name)   | -    |
// | to_world | transform | identity | grid-to-world transform                    | -    |
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

#include <femto/core/plugin.h>
#include <femto/math/transform.h>
#include <femto/render/vol_grid.h>
#include <femto/render/volume.h>

namespace femto {

class GridVolume final : public Volume {
 public:
  explicit GridVolume(const Properties& props)
      : filename_(props.getString("filename")), toWorld_(props.getTransform("to_world", Transform())) {
    read(props);
    toLocal_ = toWorld_.inverse();
    for (int corner = 0; corner < 8; ++corner)
      worldBox_.expand(toWorld_.point(Point3f(corner & 1 ? box_.max.x : box_.min.x, corner & 2 ? box_.max.y : box_.min.y,
                                              corner & 4 ? box_.max.z : box_.min.z)));
    maxValue_ = 0.0f;
    for (size_t i = 0; i < voxels(); ++i) maxValue_ = std::max(maxValue_, voxelFloat(i));
  }

  float evalFloat(const Point3f& p) const override {
    float result = 0.0f;
    interpolate(p, [&](size_t voxel, float w) { result += w * voxelFloat(voxel); });
    return result;
  }

  Color3f evalColor(const Point3f& p) const override {
    Color3f result(0.0f);
    interpolate(p, [&](size_t voxel, float w) { result += voxelColor(voxel) * w; });
    return result;
  }

  float maxFloat() const override { return maxValue_; }
  BoundingBox3f bbox() const override { return worldBox_; }

  std::string toString() const override {
    return str("GridVolume[filename=\"", filename_, "\", resolution=", res_[0], "x", res_[1], "x", res_[2],
               ", channels=", channels_, ", max=", maxValue_, "]");
  }

 private:
  size_t voxels() const { return size_t(res_[0]) * res_[1] * res_[2]; }
  float voxelFloat(size_t i) const {
    if (channels_ == 1) return data_[i];
    return (data_[3 * i] + data_[3 * i + 1] + data_[3 * i + 2]) / 3.0f;
  }
  Color3f voxelColor(size_t i) const {
    if (channels_ == 1) return Color3f(data_[i]);
    return {data_[3 * i], data_[3 * i + 1], data_[3 * i + 2]};
  }

  /// Call f(voxel index, trilinear weight) for the (up to) 8 vertices around
  /// world point `p`; nothing outside the grid's box.
  template <typename F>
  void interpolate(const Point3f& p, F&& f) const {
    Point3f local = toLocal_.point(p);
    if (!box_.contains(local)) return;
    std::array<int, 3> i0;
    std::array<float, 3> frac;
    for (int a = 0; a < 3; ++a) {
      float extent = box_.max[a] - box_.min[a];
      float g = extent > 0.0f ? (local[a] - box_.min[a]) / extent * float(res_[a] - 1) : 0.0f;
      // The last cell includes its far face: g == res - 1 interpolates with weight 1 on the last sample.
      int cell = std::clamp(int(std::floor(g)), 0, std::max(res_[a] - 2, 0));
      i0[a] = cell;
      frac[a] = res_[a] > 1 ? std::clamp(g - float(cell), 0.0f, 1.0f) : 0.0f;
    }
    for (int corner = 0; corner < 8; ++corner) {
      float w = 1.0f;
      size_t index[3];
      bool skip = false;
      for (int a = 0; a < 3; ++a) {
        int bit = (corner >> a) & 1;
        w *= bit ? frac[a] : 1.0f - frac[a];
        index[a] = size_t(i0[a] + bit);
        if (index[a] >= size_t(res_[a])) skip = true;  // a dimension with one sample
      }
      if (skip || w == 0.0f) continue;
      f((index[2] * res_[1] + index[1]) * res_[0] + index[0], w);
    }
  }

  void read(const Properties& props) {
    VolGrid grid = readVolGrid(filename_, [&](const std::string& why) {
      props.raise("filename", str("grid volume file \"", filename_, "\": ", why));
    });
    res_ = grid.res;
    channels_ = grid.channels;
    box_ = grid.box;
    data_ = std::move(grid.data);
  }

  std::string filename_;
  Transform toWorld_, toLocal_;
  BoundingBox3f box_, worldBox_;
  std::array<int, 3> res_{1, 1, 1};
  int channels_ = 1;
  std::vector<float> data_;
  float maxValue_ = 0.0f;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::GridVolume, Volume, "gridvolume", "Trilinearly interpolated grid from a Mitsuba .vol file")
