// ply: a Stanford PLY triangle mesh, ASCII or binary (little or big endian).
// Vertices give x/y/z, optionally nx/ny/nz and texture coordinates (u/v,
// s/t, texture_u/texture_v or texture_s/texture_t); faces are lists of vertex
// indices (vertex_indices or vertex_index), polygons are fan-triangulated.
// Every PLY scalar type is accepted for every property; other elements and
// properties are skipped. Truncated or malformed files are errors naming the
// file (and, for ASCII, the line).
//
// | name         | type      | default  | meaning                                          | unit |
// |--------------|-----------|----------|--------------------------------------------------|------|
// | filename     | string    | required | PLY file (the loader resolves relative names)    | -    |
// | to_world     | transform | identity | object-to-world placement                        | -    |
// | flip_normals | boolean   | false    | reverse geometric and shading normals            | -    |
// | face_normals | boolean   | false    | ignore the file's vertex normals (flat shading)  | -    |
#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <femto/core/plugin.h>
#include <femto/render/mesh.h>

namespace femto {
namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // the items' type for lists
  bool isList = false;
  PlyType countType = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  size_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

size_t byteSize(PlyType t) {
  switch (t) {
    case PlyType::Int8: case PlyType::UInt8: return 1;
    case PlyType::Int16: case PlyType::UInt16: return 2;
    case PlyType::Int32: case PlyType::UInt32: case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 0;
}

bool parseType(const std::string& word, PlyType& t) {
  static const std::pair<const char*, PlyType> names[] = {
      {"char", PlyType::Int8},     {"int8", PlyType::Int8},      {"uchar", PlyType::UInt8},   {"uint8", PlyType::UInt8},
      {"short", PlyType::Int16},   {"int16", PlyType::Int16},    {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},
      {"int", PlyType::Int32},     {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},   {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [name, type] : names)
    if (word == name) return t = type, true;
  return false;
}

/// Reads the body after end_header: whitespace-separated numbers (ASCII,
/// tracking the line for messages) or packed binary values in either byte order.
class PlyBodyReader {
 public:
  PlyBodyReader(const std::string& data, size_t offset, PlyFormat format, int line, std::string file)
      : data_(data), pos_(offset), format_(format), line_(line), file_(std::move(file)) {}

  double read(PlyType type, const char* what) {
    return format_ == PlyFormat::Ascii ? readAscii(what) : readBinary(type, what);
  }
  /// A list length or vertex index: must be a non-negative integer.
  uint32_t readIndex(PlyType type, const char* what) {
    double v = read(type, what);
    if (!(v >= 0.0 && v <= 4294967295.0) || v != std::floor(v)) fail(str(what, " is ", v, ", not a non-negative integer"));
    return uint32_t(v);
  }
  void skip(const PlyProperty& p, const char* what) {
    size_t n = p.isList ? readIndex(p.countType, what) : 1;
    for (size_t i = 0; i < n; ++i) read(p.type, what);
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw Error(format_ == PlyFormat::Ascii ? str("PLY file \"", file_, "\", line ", line_, ": ", message)
                                            : str("PLY file \"", file_, "\" (byte ", pos_, "): ", message));
  }

 private:
  double readAscii(const char* what) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_])))
      if (data_[pos_++] == '\n') ++line_;
    if (pos_ >= data_.size()) fail(str("the file ends while reading ", what, " (truncated?)"));
    double v = 0.0;
    const char* begin = data_.data() + pos_;
    auto [end, ec] = std::from_chars(begin, data_.data() + data_.size(), v);
    if (ec != std::errc() || (end < data_.data() + data_.size() && !std::isspace(static_cast<unsigned char>(*end)))) {
      size_t len = 0;
      while (pos_ + len < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_ + len])) && len < 40) ++len;
      fail(str("expected a number for ", what, ", got \"", data_.substr(pos_, len), "\""));
    }
    pos_ = size_t(end - data_.data());
    return v;
  }

  template <typename T>
  T load() {
    T v;
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, data_.data() + pos_, sizeof(T));
    bool fileLittle = format_ == PlyFormat::BinaryLittleEndian;
    if (fileLittle != (std::endian::native == std::endian::little)) std::reverse(bytes, bytes + sizeof(T));
    std::memcpy(&v, bytes, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }

  double readBinary(PlyType type, const char* what) {
    if (pos_ + byteSize(type) > data_.size()) fail(str("the file ends while reading ", what, " (truncated?)"));
    switch (type) {
      case PlyType::Int8: return load<int8_t>();
      case PlyType::UInt8: return load<uint8_t>();
      case PlyType::Int16: return load<int16_t>();
      case PlyType::UInt16: return load<uint16_t>();
      case PlyType::Int32: return load<int32_t>();
      case PlyType::UInt32: return load<uint32_t>();
      case PlyType::Float32: return load<float>();
      case PlyType::Float64: return load<double>();
    }
    return 0.0;
  }

  const std::string& data_;
  size_t pos_;
  PlyFormat format_;
  int line_;
  std::string file_;
};

/// Index of the first property named one of `names`, or -1.
int findProperty(const PlyElement& e, std::initializer_list<const char*> names) {
  for (const char* name : names)
    for (size_t i = 0; i < e.properties.size(); ++i)
      if (e.properties[i].name == name && !e.properties[i].isList) return int(i);
  return -1;
}

}  // namespace

class PlyMesh final : public TriangleMesh {
 public:
  explicit PlyMesh(const Properties& props) : TriangleMesh(props) {
    filename_ = props.getString("filename");
    Transform toWorld = props.getTransform("to_world", Transform());
    bool flipNormals = props.getBool("flip_normals", false);
    bool faceNormals = props.getBool("face_normals", false);
    try {
      read();
      setGeometry(std::move(positions_), std::move(indices_), std::move(normals_), std::move(uvs_), toWorld,
                  flipNormals, faceNormals);
    } catch (const Error& e) {
      props.raise("filename", e.what());
    }
  }

  std::string toString() const override {
    return str("PlyMesh[filename=\"", filename_, "\", triangles=", triangleCount(), ", vertices=", vertexCount(),
               ", area=", surfaceArea(), "]");
  }

 private:
  [[noreturn]] void fail(int line, const std::string& message) const {
    throw Error(str("PLY file \"", filename_, "\", line ", line, ": ", message));
  }

  void read() {
    std::ifstream in(filename_, std::ios::binary);
    if (!in) throw Error(str("cannot open PLY file \"", filename_, "\""));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    std::string data = buffer.str();

    // --- header ---
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    size_t pos = 0;
    int line = 0;
    bool sawFormat = false, ended = false;
    while (!ended) {
      if (pos >= data.size()) fail(line, "the file ends inside the header (no end_header)");
      size_t eol = data.find('\n', pos);
      if (eol == std::string::npos) eol = data.size();
      std::string text = data.substr(pos, eol - pos);
      pos = std::min(eol + 1, data.size());
      ++line;
      if (!text.empty() && text.back() == '\r') text.pop_back();
      std::istringstream words(text);
      std::string keyword;
      words >> keyword;
      if (line == 1) {
        if (keyword != "ply") throw Error(str("\"", filename_, "\" is not a PLY file (it does not start with \"ply\")"));
        continue;
      }
      if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "format") {
        std::string name, version;
        words >> name >> version;
        if (name == "ascii") format = PlyFormat::Ascii;
        else if (name == "binary_little_endian") format = PlyFormat::BinaryLittleEndian;
        else if (name == "binary_big_endian") format = PlyFormat::BinaryBigEndian;
        else fail(line, str("unknown format \"", name, "\""));
        sawFormat = true;
      } else if (keyword == "element") {
        PlyElement e;
        long long count = -1;
        words >> e.name >> count;
        if (e.name.empty() || count < 0 || words.fail()) fail(line, "expected \"element <name> <count>\"");
        e.count = size_t(count);
        elements.push_back(std::move(e));
      } else if (keyword == "property") {
        if (elements.empty()) fail(line, "a property before any element");
        PlyProperty p;
        std::string type;
        words >> type;
        if (type == "list") {
          std::string countType, itemType;
          words >> countType >> itemType >> p.name;
          p.isList = true;
          if (!parseType(countType, p.countType) || !parseType(itemType, p.type))
            fail(line, str("unknown list types \"", countType, " ", itemType, "\""));
        } else {
          words >> p.name;
          if (!parseType(type, p.type)) fail(line, str("unknown property type \"", type, "\""));
        }
        if (p.name.empty()) fail(line, "a property without a name");
        elements.back().properties.push_back(std::move(p));
      } else if (keyword == "end_header") {
        ended = true;
      } else {
        fail(line, str("unexpected header line \"", text, "\""));
      }
    }
    if (!sawFormat) fail(line, "the header has no format line");

    // --- body ---
    PlyBodyReader body(data, pos, format, line + 1, filename_);
    bool sawVertices = false, sawFaces = false;
    for (const PlyElement& e : elements) {
      if (e.name == "vertex") {
        readVertices(e, body);
        sawVertices = true;
      } else if (e.name == "face") {
        readFaces(e, body);
        sawFaces = true;
      } else {
        for (size_t i = 0; i < e.count; ++i)
          for (const PlyProperty& p : e.properties) body.skip(p, e.name.c_str());
      }
    }
    if (!sawVertices || !sawFaces) throw Error(str("PLY file \"", filename_, "\" has no ", sawVertices ? "face" : "vertex",
                                                   " element"));
  }

  void readVertices(const PlyElement& e, PlyBodyReader& body) {
    int x = findProperty(e, {"x"}), y = findProperty(e, {"y"}), z = findProperty(e, {"z"});
    if (x < 0 || y < 0 || z < 0) throw Error(str("PLY file \"", filename_, "\": the vertex element lacks x, y or z"));
    int nx = findProperty(e, {"nx"}), ny = findProperty(e, {"ny"}), nz = findProperty(e, {"nz"});
    int u = findProperty(e, {"u", "s", "texture_u", "texture_s"});
    int v = findProperty(e, {"v", "t", "texture_v", "texture_t"});
    bool hasNormals = nx >= 0 && ny >= 0 && nz >= 0, hasUvs = u >= 0 && v >= 0;
    positions_.reserve(e.count);
    if (hasNormals) normals_.reserve(e.count);
    if (hasUvs) uvs_.reserve(e.count);
    std::vector<double> values(e.properties.size());
    for (size_t i = 0; i < e.count; ++i) {
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (p.isList) body.skip(p, "a vertex");
        else values[k] = body.read(p.type, "a vertex");
      }
      positions_.emplace_back(float(values[x]), float(values[y]), float(values[z]));
      if (hasNormals) normals_.emplace_back(float(values[nx]), float(values[ny]), float(values[nz]));
      if (hasUvs) uvs_.emplace_back(float(values[u]), float(values[v]));
    }
  }

  void readFaces(const PlyElement& e, PlyBodyReader& body) {
    int list = -1;
    for (size_t k = 0; k < e.properties.size() && list < 0; ++k)
      if (e.properties[k].isList && (e.properties[k].name == "vertex_indices" || e.properties[k].name == "vertex_index"))
        list = int(k);
    if (list < 0) throw Error(str("PLY file \"", filename_, "\": the face element has no vertex_indices list"));
    indices_.reserve(3 * e.count);
    std::vector<uint32_t> polygon;
    for (size_t i = 0; i < e.count; ++i) {
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        if (int(k) != list) {
          body.skip(p, "a face");
          continue;
        }
        uint32_t n = body.readIndex(p.countType, "a face's vertex count");
        if (n < 3) body.fail(str("face ", i, " has ", n, " vertices; a face needs at least 3"));
        polygon.resize(n);
        for (uint32_t& index : polygon) index = body.readIndex(p.type, "a vertex index");
        for (uint32_t j = 1; j + 1 < n; ++j)  // fan triangulation
          indices_.insert(indices_.end(), {polygon[0], polygon[j], polygon[j + 1]});
      }
    }
  }

  std::string filename_;
  std::vector<Point3f> positions_;
  std::vector<uint32_t> indices_;
  std::vector<Normal3f> normals_;
  std::vector<Point2f> uvs_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::PlyMesh, Shape, "ply", "Stanford PLY triangle mesh")
