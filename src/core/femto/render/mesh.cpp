#include <femto/render/mesh.h>

#include <algorithm>
#include <cmath>

#include <femto/math/warp.h>

namespace femto {

TriangleMesh::TriangleMesh(const Properties& props) : Shape(props) {}

void TriangleMesh::setGeometry(std::vector<Point3f> positions, std::vector<uint32_t> indices,
                               std::vector<Normal3f> normals, std::vector<Point2f> uvs, const Transform& toWorld,
                               bool flipNormals, bool faceNormals) {
  if (positions.empty() || indices.empty()) throw Error(str(toString(), ": the mesh has no triangles"));
  if (indices.size() % 3 != 0)
    throw Error(str(toString(), ": ", indices.size(), " vertex indices is not a multiple of 3"));
  for (size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= positions.size())
      throw Error(str(toString(), ": triangle ", i / 3, " refers to vertex ", indices[i], " but the mesh has only ",
                      positions.size(), " vertices"));
  if (!normals.empty() && normals.size() != positions.size())
    throw Error(str(toString(), ": ", normals.size(), " normals for ", positions.size(), " vertices"));
  if (!uvs.empty() && uvs.size() != positions.size())
    throw Error(str(toString(), ": ", uvs.size(), " texture coordinates for ", positions.size(), " vertices"));

  bbox_ = BoundingBox3f();
  for (auto& p : positions) {
    p = toWorld.point(p);
    bbox_.expand(p);
  }
  if (faceNormals) normals.clear();
  for (auto& n : normals) {
    n = toWorld.normal(n);
    float len = length(n);
    n = len > 0.0f ? n / len : Normal3f(0.0f);  // zero normals fall back to the face normal
  }
  positions_ = std::move(positions);
  indices_ = std::move(indices);
  normals_ = std::move(normals);
  uvs_ = std::move(uvs);
  flipNormals_ = flipNormals;

  areaCdf_.resize(triangleCount());
  double sum = 0.0;  // double: large meshes sum many small areas
  for (size_t i = 0; i < triangleCount(); ++i) {
    const Point3f& p0 = positions_[indices_[3 * i]];
    const Point3f& p1 = positions_[indices_[3 * i + 1]];
    const Point3f& p2 = positions_[indices_[3 * i + 2]];
    sum += 0.5 * double(length(cross(p1 - p0, p2 - p0)));
    areaCdf_[i] = float(sum);
  }
  area_ = float(sum);
}

PositionSample TriangleMesh::samplePosition(const Point2f& u) const {
  PositionSample ps;
  if (area_ <= 0.0f) return ps;  // pdf 0: nothing to sample
  // Pick a triangle by area; upper_bound never lands on a zero-area one
  // because its cumulative value equals its predecessor's.
  float target = u.x * area_;
  size_t i = size_t(std::upper_bound(areaCdf_.begin(), areaCdf_.end(), target) - areaCdf_.begin());
  i = std::min(i, areaCdf_.size() - 1);
  while (i > 0 && areaCdf_[i] == areaCdf_[i - 1]) --i;  // u.x rounded onto the end
  float start = i == 0 ? 0.0f : areaCdf_[i - 1];
  float triArea = areaCdf_[i] - start;
  // Reuse the leftover of u.x so one 2D sample suffices (stratification is kept).
  float ux = std::clamp((target - start) / triArea, 0.0f, 0.99999994f);
  Point2f b = warp::squareToUniformTriangle(Point2f(ux, u.y));

  uint32_t i0 = indices_[3 * i], i1 = indices_[3 * i + 1], i2 = indices_[3 * i + 2];
  float b0 = 1.0f - b.x - b.y;
  const Point3f &p0 = positions_[i0], &p1 = positions_[i1], &p2 = positions_[i2];
  ps.p = p0 * b0 + p1 * b.x + p2 * b.y;
  Normal3f n = normalize(cross(p1 - p0, p2 - p0));
  ps.n = flipNormals_ ? -n : n;
  ps.uv = uvs_.empty() ? b : uvs_[i0] * b0 + uvs_[i1] * b.x + uvs_[i2] * b.y;
  ps.pdf = 1.0f / area_;
  return ps;
}

Frame TriangleMesh::shadingFrame(const Normal3f& ns, const Vec3f& dp1, const Vec3f& dp2, uint32_t primIndex) const {
  if (uvs_.empty()) return Frame(ns);
  // With texture coordinates the tangent follows dp/du (pbrt-v4 section
  // 6.5.3; Mitsuba does the same), so anisotropic BSDFs and textures agree on
  // an orientation; Gram-Schmidt makes it orthogonal to the shading normal.
  const Point2f& uv0 = uvs_[indices_[3 * primIndex]];
  Point2f duv1 = uvs_[indices_[3 * primIndex + 1]] - uv0, duv2 = uvs_[indices_[3 * primIndex + 2]] - uv0;
  float det = duv1.x * duv2.y - duv1.y * duv2.x;
  if (!(std::abs(det) > 1e-12f)) return Frame(ns);  // degenerate uv mapping
  Vec3f dpdu = (dp1 * duv2.y - dp2 * duv1.y) / det;
  Vec3f s = dpdu - ns * dot(ns, dpdu);
  float len = length(s);
  if (!(len > 1e-12f * length(dpdu))) return Frame(ns);  // dp/du along the normal
  s = s / len;
  return Frame(s, cross(ns, s), ns);
}

void TriangleMesh::computeInteraction(const Ray& ray, float t, uint32_t primIndex, const Point2f& uv,
                                      SurfaceInteraction& si) const {
  uint32_t i0 = indices_[3 * primIndex], i1 = indices_[3 * primIndex + 1], i2 = indices_[3 * primIndex + 2];
  const Point3f &p0 = positions_[i0], &p1 = positions_[i1], &p2 = positions_[i2];
  float b1 = uv.x, b2 = uv.y, b0 = 1.0f - b1 - b2;

  // Interpolating the vertices is more accurate than o + t d far from the origin.
  si.p = p0 * b0 + p1 * b1 + p2 * b2;
  (void)ray;
  si.t = t;
  // Geometric normal from the winding (counter-clockwise = front), as Mitsuba.
  Normal3f n = normalize(cross(p1 - p0, p2 - p0));
  if (flipNormals_) n = -n;
  si.n = n;

  Normal3f ns = n;
  if (!normals_.empty()) {
    Normal3f interp = normals_[i0] * b0 + normals_[i1] * b1 + normals_[i2] * b2;
    float len = length(interp);
    if (len > 0.0f) ns = flipNormals_ ? -(interp / len) : interp / len;
  }
  si.sh = shadingFrame(ns, p1 - p0, p2 - p0, primIndex);
  si.uv = uvs_.empty() ? Point2f(b1, b2) : uvs_[i0] * b0 + uvs_[i1] * b1 + uvs_[i2] * b2;
  si.primIndex = primIndex;
}

}  // namespace femto
