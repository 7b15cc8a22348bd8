// cube: the box [-1, 1]^3 with outward normals, placed by `to_world`. Each
// face has its own four vertices (flat normals, a full [0,1]^2 uv square), so
// 24 vertices and 12 triangles go to the core's triangle mesh.
//
// | name         | type      | default  | meaning                              | unit |
// |--------------|-----------|----------|--------------------------------------|------|
// | to_world     | transform | identity | object-to-world placement            | -    |
// | flip_normals | boolean   | false    | make the normals point inward        | -    |
#include <femto/core/plugin.h>
#include <femto/render/mesh.h>

namespace femto {

class Cube final : public TriangleMesh {
 public:
  explicit Cube(const Properties& props) : TriangleMesh(props) {
    toWorld_ = props.getTransform("to_world", Transform());
    flipNormals_ = props.getBool("flip_normals", false);
    std::vector<Point3f> positions;
    std::vector<Normal3f> normals;
    std::vector<Point2f> uvs;
    std::vector<uint32_t> indices;
    // One face per axis and sign: the face's normal n and two in-plane axes
    // (a, b) with a x b = n, so the corners below run counter-clockwise seen
    // from outside and the geometric normal points outward.
    for (int axis = 0; axis < 3; ++axis)
      for (float sign : {-1.0f, 1.0f}) {
        Vec3f n(0.0f), a(0.0f), b(0.0f);
        n[axis] = sign;
        a[(axis + 1) % 3] = sign;
        b[(axis + 2) % 3] = 1.0f;
        uint32_t base = uint32_t(positions.size());
        const Point2f corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (const Point2f& c : corners) {
          positions.push_back(n + a * (2.0f * c.x - 1.0f) + b * (2.0f * c.y - 1.0f));
          normals.push_back(n);
          uvs.push_back(c);
        }
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(base + i);
      }
    setGeometry(std::move(positions), std::move(indices), std::move(normals), std::move(uvs), toWorld_, flipNormals_,
                false);
  }

  std::string toString() const override {
    return str("Cube[to_world=\n", toWorld_.matrix(), ", flip_normals=", flipNormals_ ? "true" : "false",
               ", area=", surfaceArea(), "]");
  }

 private:
  Transform toWorld_;
  bool flipNormals_ = false;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::Cube, Shape, "cube", "Box [-1,1]^3 with outward normals")
