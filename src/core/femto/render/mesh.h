#pragma once
// Indexed triangle mesh: the one shape representation Embree intersects
// natively. Mesh plugins (obj, ply, serialized, rectangle, cube) fill it.
#include <cstdint>
#include <vector>

#include <femto/math/transform.h>
#include <femto/render/shape.h>

namespace femto {

class TriangleMesh : public Shape {
 public:
  explicit TriangleMesh(const Properties& props);

  /// Hand over the geometry (object space) and bake `toWorld` into it.
  /// `normals` and `uvs` are per vertex and may be empty. `flipNormals`
  /// reverses geometric and shading normals; `faceNormals` drops vertex
  /// normals (flat shading). Throws on out-of-range indices or an empty mesh;
  /// degenerate (zero-area) triangles are kept but never sampled.
  void setGeometry(std::vector<Point3f> positions, std::vector<uint32_t> indices, std::vector<Normal3f> normals,
                   std::vector<Point2f> uvs, const Transform& toWorld, bool flipNormals, bool faceNormals);

  const TriangleMesh* asMesh() const override { return this; }
  BoundingBox3f bbox() const override { return bbox_; }
  float surfaceArea() const override { return area_; }
  PositionSample samplePosition(const Point2f& u) const override;
  /// `uv` are Embree's barycentrics (u, v) of vertices 1 and 2.
  void computeInteraction(const Ray& ray, float t, uint32_t primIndex, const Point2f& uv,
                          SurfaceInteraction& si) const override;

  const std::vector<Point3f>& positions() const { return positions_; }
  const std::vector<uint32_t>& indices() const { return indices_; }
  const std::vector<Normal3f>& normals() const { return normals_; }
  const std::vector<Point2f>& uvs() const { return uvs_; }
  size_t triangleCount() const { return indices_.size() / 3; }
  size_t vertexCount() const { return positions_.size(); }

 private:
  /// Shading frame around `ns`: tangent along dp/du when the mesh has uvs.
  Frame shadingFrame(const Normal3f& ns, const Vec3f& dp1, const Vec3f& dp2, uint32_t primIndex) const;

  std::vector<Point3f> positions_;
  std::vector<uint32_t> indices_;
  std::vector<Normal3f> normals_;
  std::vector<Point2f> uvs_;
  std::vector<float> areaCdf_;  // cumulative triangle areas, for samplePosition
  bool flipNormals_ = false;
  BoundingBox3f bbox_;
  float area_ = 0.0f;
};

}  // namespace femto
