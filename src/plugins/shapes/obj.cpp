// obj: a Wavefront OBJ triangle mesh read with tinyobjloader. Polygons are
// triangulated; all groups of the file become one shape; materials are ignored
// (the scene file gives the BSDF).
//
// | name         | type      | default  | meaning                                          | unit |
// |--------------|-----------|----------|--------------------------------------------------|------|
// | filename     | string    | required | OBJ file (the loader resolves relative names)    | -    |
// | to_world     | transform | identity | object-to-world placement                        | -    |
// | flip_normals | boolean   | false    | reverse geometric and shading normals            | -    |
// | face_normals | boolean   | false    | ignore the file's vertex normals (flat shading)  | -    |
// | flip_tex_coords | boolean | true   | use v' = 1 - v (OBJ puts v = 0 at the bottom of  | -    |
// |              |           |          | an image, femto's textures at the top; Mitsuba's |      |
// |              |           |          | default, so textured scenes match Mitsuba)       |      |
#include <filesystem>
#include <map>
#include <tuple>

#include <tiny_obj_loader.h>

#include <femto/core/log.h>
#include <femto/core/plugin.h>
#include <femto/render/mesh.h>

namespace femto {
namespace {

/// OBJ faces index positions, normals and uvs separately; a renderer vertex
/// is one distinct (position, normal, uv) triple.
struct ObjVertexKey {
  int p, n, t;
  bool operator<(const ObjVertexKey& o) const { return std::tie(p, n, t) < std::tie(o.p, o.n, o.t); }
};

}  // namespace

class ObjMesh final : public TriangleMesh {
 public:
  explicit ObjMesh(const Properties& props) : TriangleMesh(props) {
    filename_ = props.getString("filename");
    Transform toWorld = props.getTransform("to_world", Transform());
    bool flipNormals = props.getBool("flip_normals", false);
    bool faceNormals = props.getBool("face_normals", false);
    bool flipTexCoords = props.getBool("flip_tex_coords", true);
    // The loader has already resolved relative names against the scene's folder.
    std::filesystem::path path(filename_);
    if (!std::filesystem::is_regular_file(path))
      props.raise("filename", str("cannot open OBJ file \"", path.string(), "\": no such file"));

    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = path.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path.string(), config)) {
      std::string why = reader.Error();
      while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
      props.raise("filename", str("cannot read OBJ file \"", path.string(), "\": ", why.empty() ? "unknown error" : why));
    }
    if (!reader.Warning().empty()) logDebug("obj \"", path.string(), "\": ", reader.Warning());

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    std::vector<Point3f> positions;
    std::vector<Normal3f> normals;
    std::vector<Point2f> uvs;
    std::vector<uint32_t> indices;
    // Normals and uvs are kept only when every face vertex has them.
    bool allNormals = true, allUvs = true;
    for (const tinyobj::shape_t& shape : reader.GetShapes())
      for (const tinyobj::index_t& idx : shape.mesh.indices) {
        allNormals &= idx.normal_index >= 0;
        allUvs &= idx.texcoord_index >= 0;
      }
    std::map<ObjVertexKey, uint32_t> vertexOf;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
      const tinyobj::mesh_t& mesh = shape.mesh;
      size_t offset = 0;
      for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
        size_t count = mesh.num_face_vertices[f];
        if (count != 3)  // triangulation leaves only degenerate faces (points, lines) behind
          props.raise("filename", str("OBJ file \"", path.string(), "\": face ", f + 1, " of group \"", shape.name,
                                      "\" has ", count, " vertices; only polygons are supported"));
        for (size_t k = 0; k < 3; ++k) {
          const tinyobj::index_t& idx = mesh.indices[offset + k];
          ObjVertexKey key{idx.vertex_index, allNormals ? idx.normal_index : -1, allUvs ? idx.texcoord_index : -1};
          auto [it, inserted] = vertexOf.emplace(key, uint32_t(positions.size()));
          if (inserted) {
            auto missing = [](int i, size_t stride, size_t size) { return i < 0 || stride * size_t(i) + stride > size; };
            if (missing(key.p, 3, attrib.vertices.size()) || (allNormals && missing(key.n, 3, attrib.normals.size())) ||
                (allUvs && missing(key.t, 2, attrib.texcoords.size())))
              props.raise("filename", str("OBJ file \"", path.string(), "\": face ", f + 1,
                                          " refers to a vertex, normal or texture coordinate that does not exist"));
            positions.emplace_back(attrib.vertices[3 * key.p], attrib.vertices[3 * key.p + 1],
                                   attrib.vertices[3 * key.p + 2]);
            if (allNormals)
              normals.emplace_back(attrib.normals[3 * key.n], attrib.normals[3 * key.n + 1], attrib.normals[3 * key.n + 2]);
            if (allUvs) {
              float v = attrib.texcoords[2 * key.t + 1];
              uvs.emplace_back(attrib.texcoords[2 * key.t], flipTexCoords ? 1.0f - v : v);
            }
          }
          indices.push_back(it->second);
        }
        offset += count;
      }
    }
    if (indices.empty()) props.raise("filename", str("OBJ file \"", path.string(), "\" contains no faces"));
    try {
      setGeometry(std::move(positions), std::move(indices), std::move(normals), std::move(uvs), toWorld, flipNormals,
                  faceNormals);
    } catch (const Error& e) {
      props.raise("filename", str("OBJ file \"", path.string(), "\": ", e.what()));
    }
  }

  std::string toString() const override {
    return str("ObjMesh[filename=\"", filename_, "\", triangles=", triangleCount(), ", vertices=", vertexCount(),
               ", area=", surfaceArea(), "]");
  }

 private:
  std::string filename_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::ObjMesh, Shape, "obj", "Wavefront OBJ triangle mesh")
