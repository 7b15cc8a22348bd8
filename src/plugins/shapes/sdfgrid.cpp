// sdfgrid: Mitsuba 3's signed-distance grid shape. The .vol file's values
// are samples of a signed distance on the grid's vertices over the unit cube
// [0,1]^3 (sample (0,0,0) at the origin, (nx-1, ny-1, nz-1) at (1,1,1),
// whatever box the file stores, as Mitsuba 3 places it); the surface is the
// zero level set, negative inside. femto triangulates it once at load by
// marching tetrahedra (each cell split into six tetrahedra around its main
// diagonal; vertices where the samples' linear interpolation along an edge
// crosses zero, shared between cells, so the mesh is closed): its vertices
// lie on the trilinear surface Mitsuba intersects, its triangles within
// O(cell^2) of it (docs/rendering.md has the measured error). Shading normals:
// "smooth" (Mitsuba's default) interpolates the grid's central-difference
// gradient to the vertices; "analytic" uses the triangles' own normals.
//
// | name     | type      | default  | meaning                                          | unit |
// |----------|-----------|----------|--------------------------------------------------|------|
// | filename | string    | required | single-channel .vol file (render/vol_grid.h)      | -    |
// | normals  | string    | "smooth" | "smooth" or "analytic" shading normals           | -    |
// | to_world | transform | identity | unit cube to world                               | -    |
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include <femto/core/plugin.h>
#include <femto/render/mesh.h>
#include <femto/render/vol_grid.h>

namespace femto {
namespace {

/// The grid's samples and their central-difference gradients.
struct Sdf {
  std::array<int, 3> n;
  std::vector<float> v;
  size_t index(int x, int y, int z) const { return (size_t(z) * size_t(n[1]) + size_t(y)) * size_t(n[0]) + size_t(x); }
  float at(int x, int y, int z) const { return v[index(x, y, z)]; }
  Vec3f gradient(int x, int y, int z) const {
    const int c[3] = {x, y, z};
    Vec3f g(0.0f);
    for (int a = 0; a < 3; ++a) {
      int lo[3] = {x, y, z}, hi[3] = {x, y, z};
      lo[a] = std::max(c[a] - 1, 0);
      hi[a] = std::min(c[a] + 1, n[a] - 1);
      // Per unit of object space (the cube is 1 wide: a cell is 1 / (n - 1)).
      g[a] = (at(hi[0], hi[1], hi[2]) - at(lo[0], lo[1], lo[2])) * float(n[a] - 1) / float(hi[a] - lo[a]);
    }
    return g;
  }
};

}  // namespace

class SdfGrid final : public TriangleMesh {
 public:
  explicit SdfGrid(const Properties& props) : TriangleMesh(props) {
    toWorld_ = props.getTransform("to_world", Transform());
    const std::string filename = props.getString("filename");
    smooth_ = props.getEnum("normals", true, {{"smooth", true, "interpolated grid gradients"},
                                              {"analytic", false, "the triangles' own normals"}});
    VolGrid grid = readVolGrid(filename, [&](const std::string& why) {
      props.raise("filename", str("sdfgrid file \"", filename, "\": ", why));
    });
    if (grid.channels != 1) props.raise("filename", str("sdfgrid file \"", filename, "\" has ", grid.channels,
                                                        " channels; a signed distance grid has 1"));
    for (int a = 0; a < 3; ++a)
      if (grid.res[a] < 2)
        props.raise("filename", str("sdfgrid file \"", filename, "\" is ", grid.res[0], "x", grid.res[1], "x",
                                    grid.res[2], ": it needs at least 2 samples along every axis"));
    Sdf sdf{grid.res, std::move(grid.data)};
    triangulate(sdf);
    if (indices_.empty())
      props.raise("filename", str("sdfgrid file \"", filename, "\" has no zero crossing: the surface is empty"));
    setGeometry(std::move(positions_), std::move(indices_), std::move(normals_), {}, toWorld_, false, !smooth_);
  }

  std::string toString() const override {
    return str("SdfGrid[to_world=\n", toWorld_.matrix(), ", normals=", smooth_ ? "smooth" : "analytic",
               ", area=", surfaceArea(), "]");
  }

 private:
  /// Marching tetrahedra over every cell (see the header).
  void triangulate(const Sdf& sdf) {
    const std::array<int, 3>& n = sdf.n;
    // The six tetrahedra of a cell around its diagonal 0-7 (corner bits: x 1, y 2, z 4).
    static constexpr int Tets[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};
    std::unordered_map<uint64_t, uint32_t> edgeVertex;
    auto vertexOn = [&](const int a[3], const int b[3]) -> uint32_t {
      size_t ia = sdf.index(a[0], a[1], a[2]), ib = sdf.index(b[0], b[1], b[2]);
      if (ia > ib) std::swap(ia, ib), std::swap(a, b);
      const uint64_t key = uint64_t(ia) * uint64_t(sdf.v.size()) + uint64_t(ib);
      auto [it, fresh] = edgeVertex.emplace(key, uint32_t(positions_.size()));
      if (!fresh) return it->second;
      const float fa = sdf.v[ia], fb = sdf.v[ib];
      const float t = fa / (fa - fb);
      Point3f p(0.0f);
      for (int k = 0; k < 3; ++k)
        p[k] = (float(a[k]) + t * float(b[k] - a[k])) / float(n[k] - 1);
      positions_.push_back(p);
      if (smooth_) {
        Vec3f g = sdf.gradient(a[0], a[1], a[2]) * (1.0f - t) + sdf.gradient(b[0], b[1], b[2]) * t;
        float len = length(g);
        normals_.push_back(Normal3f(len > 0.0f ? g / len : Vec3f(0.0f, 0.0f, 1.0f)));
      }
      return it->second;
    };
    for (int z = 0; z + 1 < n[2]; ++z)
      for (int y = 0; y + 1 < n[1]; ++y)
        for (int x = 0; x + 1 < n[0]; ++x) {
          int corner[8][3];
          float value[8];
          for (int c = 0; c < 8; ++c) {
            corner[c][0] = x + (c & 1), corner[c][1] = y + ((c >> 1) & 1), corner[c][2] = z + ((c >> 2) & 1);
            value[c] = sdf.at(corner[c][0], corner[c][1], corner[c][2]);
          }
          for (const auto& tet : Tets) {
            int inside[4], outside[4], ni = 0, no = 0;
            for (int k : tet) (value[k] < 0.0f ? inside[ni++] : outside[no++]) = k;
            if (ni == 0 || no == 0) continue;
            // Points toward positive distance: from an inside corner to an outside one.
            Vec3f out(0.0f);
            for (int k = 0; k < 3; ++k) out[k] = float(corner[outside[0]][k] - corner[inside[0]][k]) / float(n[k] - 1);
            if (ni == 1 || no == 1) {
              const int apex = ni == 1 ? inside[0] : outside[0];
              const int* others = ni == 1 ? outside : inside;
              addTriangle(vertexOn(corner[apex], corner[others[0]]), vertexOn(corner[apex], corner[others[1]]),
                          vertexOn(corner[apex], corner[others[2]]), out);
            } else {
              // Two inside, two outside: the quad on the four crossing edges, as two triangles.
              uint32_t q[4] = {vertexOn(corner[inside[0]], corner[outside[0]]), vertexOn(corner[inside[0]], corner[outside[1]]),
                               vertexOn(corner[inside[1]], corner[outside[1]]), vertexOn(corner[inside[1]], corner[outside[0]])};
              addTriangle(q[0], q[1], q[2], out);
              addTriangle(q[0], q[2], q[3], out);
            }
          }
        }
  }

  /// A triangle wound so that its normal points along `out` (object space).
  void addTriangle(uint32_t a, uint32_t b, uint32_t c, const Vec3f& out) {
    const Vec3f normal = cross(positions_[b] - positions_[a], positions_[c] - positions_[a]);
    if (!(length(normal) > 0.0f)) return;  // a degenerate sliver (a crossing at a corner)
    if (dot(normal, out) < 0.0f) std::swap(b, c);
    indices_.insert(indices_.end(), {a, b, c});
  }

  Transform toWorld_;
  bool smooth_ = true;
  std::vector<Point3f> positions_;
  std::vector<Normal3f> normals_;
  std::vector<uint32_t> indices_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::SdfGrid, Shape, "sdfgrid", "Signed distance grid (Mitsuba 3), triangulated at load")
