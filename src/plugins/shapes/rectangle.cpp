// rectangle: the square [-1, 1]^2 in the plane z = 0 with normal +z, placed
// by `to_world`. Two triangles handed to the core's triangle mesh.
//
// | name         | type      | default  | meaning                                  | unit |
// |--------------|-----------|----------|------------------------------------------|------|
// | to_world     | transform | identity | object-to-world placement                | -    |
// | flip_normals | boolean   | false    | make the normal point along -z instead   | -    |
#include <femto/core/plugin.h>
#include <femto/render/mesh.h>

namespace femto {

class Rectangle final : public TriangleMesh {
 public:
  explicit Rectangle(const Properties& props) : TriangleMesh(props) {
    toWorld_ = props.getTransform("to_world", Transform());
    flipNormals_ = props.getBool("flip_normals", false);
    std::vector<Point3f> positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    std::vector<Normal3f> normals(4, Normal3f(0, 0, 1));
    std::vector<Point2f> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    // Counter-clockwise seen from +z, so the geometric normal is +z too.
    std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3};
    setGeometry(std::move(positions), std::move(indices), std::move(normals), std::move(uvs), toWorld_, flipNormals_,
                false);
  }

  std::string toString() const override {
    return str("Rectangle[to_world=\n", toWorld_.matrix(), ", flip_normals=", flipNormals_ ? "true" : "false",
               ", area=", surfaceArea(), "]");
  }

 private:
  Transform toWorld_;
  bool flipNormals_ = false;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::Rectangle, Shape, "rectangle", "Square [-1,1]^2 in the z = 0 plane")
