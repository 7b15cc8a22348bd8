// serialized: a mesh from Mitsuba's binary ".serialized" format. A file is a
// sequence of meshes followed by a dictionary of their byte offsets; each
// mesh is a little-endian header (format id 0x041C, version 3 or 4) followed
// by a zlib stream holding: uint32 flags, (version 4) a NUL-terminated name,
// uint64 vertex and triangle counts, positions, then per the flags normals
// (0x0001), uvs (0x0002), colours (0x0008, ignored), and the triangle indices
// (uint32, or uint64 above 2^32 vertices). Flag 0x0010 asks for face normals;
// 0x1000 / 0x2000 say single / double precision. The dictionary is one offset
// per mesh (uint64 in version 4, uint32 in version 3) and then the uint32 mesh
// count, ending the file.
//
// | name         | type      | default  | meaning                                          | unit |
// |--------------|-----------|----------|--------------------------------------------------|------|
// | filename     | string    | required | .serialized file (the loader resolves the path)  | -    |
// | shape_index  | integer   | 0        | which mesh of the file                           | -    |
// | to_world     | transform | identity | object-to-world placement                        | -    |
// | flip_normals | boolean   | false    | reverse geometric and shading normals            | -    |
// | face_normals | boolean   | false    | ignore the file's vertex normals (flat shading)  | -    |
#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <sstream>

#include <zlib.h>

#include <femto/core/plugin.h>
#include <femto/render/mesh.h>

namespace femto {
namespace {

constexpr uint16_t SerializedFormatId = 0x041C;
enum SerializedFlags : uint32_t {
  HasNormals = 0x0001,
  HasUvs = 0x0002,
  HasColors = 0x0008,
  FaceNormals = 0x0010,
  SinglePrecision = 0x1000,
  DoublePrecision = 0x2000,
};

/// A shape_index the file does not have (reported at the parameter, not the file name).
struct ShapeIndexError : Error {
  using Error::Error;
};

/// Little-endian reads from a byte buffer, each checked against its end.
class ByteReader {
 public:
  ByteReader(const std::string& bytes, size_t pos, std::string what) : bytes_(bytes), pos_(pos), what_(std::move(what)) {}

  template <typename T>
  T read() {
    need(sizeof(T));
    unsigned char b[sizeof(T)];
    std::memcpy(b, bytes_.data() + pos_, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
    T v;
    std::memcpy(&v, b, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  /// A float or double, by the mesh's precision.
  float readReal(bool isDouble) { return isDouble ? float(read<double>()) : read<float>(); }
  /// `n` consecutive reals (in order: function arguments would be evaluated in any order).
  template <int N>
  std::array<float, N> readReals(bool isDouble) {
    std::array<float, N> v;
    for (float& x : v) x = readReal(isDouble);
    return v;
  }
  std::string readCString() {
    size_t end = bytes_.find('\0', pos_);
    if (end == std::string::npos) throw Error(str(what_, " ends inside the mesh name"));
    std::string s = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return s;
  }
  void need(size_t n) const {
    if (pos_ + n > bytes_.size()) throw Error(str(what_, " ends early (truncated?)"));
  }
  size_t remaining() const { return bytes_.size() - pos_; }

 private:
  const std::string& bytes_;
  size_t pos_;
  std::string what_;
};

/// Inflate the zlib stream starting at `offset`, up to its end marker.
std::string inflateFrom(const std::string& file, size_t offset, const std::string& what) {
  z_stream zs{};
  if (inflateInit(&zs) != Z_OK) throw Error(str(what, ": cannot initialise zlib"));
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(file.data() + offset));
  zs.avail_in = uInt(file.size() - offset);
  std::string out;
  int status = Z_OK;
  while (status == Z_OK) {
    size_t done = out.size();
    out.resize(done + (1u << 20));
    zs.next_out = reinterpret_cast<Bytef*>(out.data() + done);
    zs.avail_out = uInt(out.size() - done);
    status = inflate(&zs, Z_NO_FLUSH);
    out.resize(out.size() - zs.avail_out);
    if (status == Z_BUF_ERROR && zs.avail_in > 0) status = Z_OK;  // output full: grow and continue
  }
  inflateEnd(&zs);
  if (status != Z_STREAM_END)
    throw Error(str(what, ": corrupt compressed data (zlib: ", zs.msg ? zs.msg : (status == Z_BUF_ERROR ? "truncated" : "error"),
                    ")"));
  return out;
}

}  // namespace

class SerializedMesh final : public TriangleMesh {
 public:
  explicit SerializedMesh(const Properties& props) : TriangleMesh(props) {
    filename_ = props.getString("filename");
    int64_t index = props.getInt("shape_index", 0, 0, Properties::Unbounded);
    Transform toWorld = props.getTransform("to_world", Transform());
    bool flipNormals = props.getBool("flip_normals", false);
    bool faceNormals = props.getBool("face_normals", false);
    shapeIndex_ = uint32_t(index);
    try {
      read(faceNormals);
      setGeometry(std::move(positions_), std::move(indices_), std::move(normals_), std::move(uvs_), toWorld,
                  flipNormals, faceNormals);
    } catch (const ShapeIndexError& e) {
      props.raise("shape_index", e.what());
    } catch (const Error& e) {
      props.raise("filename", e.what());
    }
  }

  std::string toString() const override {
    return str("SerializedMesh[filename=\"", filename_, "\", shape_index=", shapeIndex_, ", name=\"", name_,
               "\", triangles=", triangleCount(), ", vertices=", vertexCount(), "]");
  }

 private:
  void read(bool& faceNormals) {
    std::ifstream in(filename_, std::ios::binary);
    if (!in) throw Error(str("cannot open serialized file \"", filename_, "\""));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string file = buffer.str();
    const std::string what = str("serialized file \"", filename_, "\"");

    // The version of the first mesh decides the width of the dictionary's offsets.
    ByteReader start(file, 0, what);
    uint16_t format = start.read<uint16_t>(), version = start.read<uint16_t>();
    if (format != SerializedFormatId)
      throw Error(str(what, " is not a Mitsuba serialized mesh (format id 0x", std::hex, format, ", expected 0x41c)"));
    if (version != 3 && version != 4) throw Error(str(what, " has version ", version, "; only 3 and 4 are supported"));
    if (file.size() < 8) throw Error(str(what, " ends early (truncated?)"));
    ByteReader tail(file, file.size() - 4, what);
    uint32_t count = tail.read<uint32_t>();
    size_t offsetSize = version == 4 ? 8 : 4;
    if (count == 0 || size_t(count) * offsetSize + 4 > file.size())
      throw Error(str(what, ": the mesh dictionary at the end of the file is corrupt (", count, " meshes)"));
    if (shapeIndex_ >= count)
      throw ShapeIndexError(str(what, " holds ", count, " mesh", count == 1 ? "" : "es", "; shape_index ", shapeIndex_,
                      " is out of range"));
    ByteReader dictionary(file, file.size() - 4 - size_t(count) * offsetSize + shapeIndex_ * offsetSize, what);
    uint64_t offset = version == 4 ? dictionary.read<uint64_t>() : dictionary.read<uint32_t>();
    if (offset + 4 > file.size()) throw Error(str(what, ": mesh ", shapeIndex_, " has offset ", offset, " past the end"));

    ByteReader header(file, size_t(offset), what);
    if (header.read<uint16_t>() != SerializedFormatId)
      throw Error(str(what, ": mesh ", shapeIndex_, " at offset ", offset, " has no 0x041C header"));
    uint16_t meshVersion = header.read<uint16_t>();
    if (meshVersion != 3 && meshVersion != 4)
      throw Error(str(what, ": mesh ", shapeIndex_, " has version ", meshVersion, "; only 3 and 4 are supported"));

    std::string mesh = inflateFrom(file, size_t(offset) + 4, str(what, ", mesh ", shapeIndex_));
    ByteReader r(mesh, 0, str(what, ", mesh ", shapeIndex_));
    uint32_t flags = r.read<uint32_t>();
    bool isDouble = flags & DoublePrecision;
    if (isDouble && (flags & SinglePrecision)) throw Error(str(what, ": mesh ", shapeIndex_, " claims both precisions"));
    if (meshVersion == 4) name_ = r.readCString();
    uint64_t vertices = r.read<uint64_t>(), triangles = r.read<uint64_t>();
    size_t real = isDouble ? 8 : 4;
    // Check sizes before allocating, so a corrupt count cannot ask for terabytes.
    uint64_t perVertex = 3 * real + ((flags & HasNormals) ? 3 * real : 0) + ((flags & HasUvs) ? 2 * real : 0) +
                         ((flags & HasColors) ? 3 * real : 0);
    uint64_t indexSize = vertices > 0xFFFFFFFFull ? 8 : 4;
    if (vertices > r.remaining() / perVertex || triangles > (r.remaining() - vertices * perVertex) / (3 * indexSize))
      throw Error(str(what, ", mesh ", shapeIndex_, ": ", vertices, " vertices and ", triangles,
                      " triangles do not fit in the mesh's data (truncated?)"));
    if (vertices > 0xFFFFFFFFull) throw Error(str(what, ": meshes above 2^32 vertices are not supported"));

    positions_.resize(vertices);
    for (auto& p : positions_) {
      auto v = r.readReals<3>(isDouble);
      p = Point3f(v[0], v[1], v[2]);
    }
    if (flags & HasNormals) {
      normals_.resize(vertices);
      for (auto& n : normals_) {
        auto v = r.readReals<3>(isDouble);
        n = Normal3f(v[0], v[1], v[2]);
      }
    }
    if (flags & HasUvs) {
      uvs_.resize(vertices);
      for (auto& uv : uvs_) {
        auto v = r.readReals<2>(isDouble);
        uv = Point2f(v[0], v[1]);
      }
    }
    if (flags & HasColors)
      for (uint64_t i = 0; i < 3 * vertices; ++i) r.readReal(isDouble);  // colours are not used
    indices_.resize(3 * triangles);
    for (auto& i : indices_) i = r.read<uint32_t>();
    if (flags & FaceNormals) faceNormals = true;
  }

  std::string filename_, name_;
  uint32_t shapeIndex_ = 0;
  std::vector<Point3f> positions_;
  std::vector<uint32_t> indices_;
  std::vector<Normal3f> normals_;
  std::vector<Point2f> uvs_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::SerializedMesh, Shape, "serialized", "Mitsuba serialized triangle mesh")
