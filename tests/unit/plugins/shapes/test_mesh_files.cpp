// ply and serialized mesh plugins: files written here (every PLY encoding and
// several property types; serialized files with several meshes, both
// precisions and both versions) are read back, plus the Stanford bunny when
// /work/shared/meshes is present. Truncated and malformed files must give
// errors that name the file.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <zlib.h>

#include <femto/render/mesh.h>

#include "plugin_util.h"

using namespace femto;
using namespace femto::test;
namespace fs = std::filesystem;

namespace {

fs::path tempFile(const std::string& name) {
  fs::path dir = fs::path(::testing::TempDir()) / "femto_mesh_files";
  fs::create_directories(dir);
  return dir / name;
}

std::shared_ptr<TriangleMesh> loadMesh(const std::string& type, const fs::path& file, Properties props = {}) {
  props.setPluginName(type);
  props.setString("filename", file.string());
  auto shape = createPlugin<Shape>(ObjectKind::Shape, props);
  auto mesh = std::dynamic_pointer_cast<TriangleMesh>(shape);
  if (!mesh) throw Error("not a mesh");
  return mesh;
}

void expectNear(const Vec3f& a, const Vec3f& b, float eps = 1e-6f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

void writeBytes(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

// ---------------------------------------------------------------- PLY writer

/// Appends values in one PLY encoding.
struct PlyEncoder {
  std::string format;  // "ascii", "binary_little_endian", "binary_big_endian"
  std::string body;

  template <typename T>
  void put(double value) {
    if (format == "ascii") {
      body += str(value, ' ');
      return;
    }
    T v = T(value);
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    bool little = format == "binary_little_endian";
    if (little != (std::endian::native == std::endian::little)) std::reverse(b, b + sizeof(T));
    body.append(reinterpret_cast<const char*>(b), sizeof(T));
  }
  void endLine() {
    if (format == "ascii") body += '\n';
  }
};

/// A quad (0,0,0)-(1,0,0)-(1,1,0)-(0,1,0) and a triangle (0,1,4) rising to
/// (0.5, 0, 1): area 1 + 0.5. Mixed property types, an ignored vertex
/// property, an extra element and a face property after the index list
/// exercise the skipping.
std::string plyFile(const std::string& format) {
  const double pos[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0, 1}};
  PlyEncoder enc{format, {}};
  for (int i = 0; i < 5; ++i) {
    enc.put<double>(pos[i][0]);
    enc.put<float>(pos[i][1]);
    enc.put<int16_t>(pos[i][2]);
    enc.put<float>(0.0);       // nx
    enc.put<int8_t>(0.0);      // ny
    enc.put<double>(1.0);      // nz
    enc.put<float>(7.5);       // confidence (ignored)
    enc.put<float>(pos[i][0]); // texture_u
    enc.put<uint8_t>(pos[i][1]);  // texture_v
    enc.endLine();
  }
  enc.put<uint8_t>(4);
  for (int i : {0, 1, 2, 3}) enc.put<uint32_t>(i);
  enc.put<int32_t>(-1);  // flags (ignored)
  enc.endLine();
  enc.put<uint8_t>(3);
  for (int i : {0, 1, 4}) enc.put<uint32_t>(i);
  enc.put<int32_t>(-2);
  enc.endLine();
  enc.put<uint16_t>(2);  // one "edge" element, a list of two shorts
  enc.put<int16_t>(0);
  enc.put<int16_t>(1);
  enc.endLine();
  return str("ply\nformat ", format, " 1.0\ncomment written by test_mesh_files\nelement vertex 5\n",
             "property double x\nproperty float y\nproperty short z\nproperty float nx\nproperty char ny\n",
             "property double nz\nproperty float confidence\nproperty float texture_u\nproperty uchar texture_v\n",
             "element face 2\nproperty list uchar uint vertex_indices\nproperty int flags\n",
             "element edge 1\nproperty list ushort short vertices\nend_header\n", enc.body);
}

// --------------------------------------------------------- serialized writer

struct SerializedMeshData {
  bool doublePrecision = false;
  bool faceNormals = false;
  std::string name = "mesh";
  std::vector<double> positions, normals, uvs;  // 3, 3, 2 per vertex
  std::vector<uint32_t> indices;
};

template <typename T>
void putLE(std::string& out, T v) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (std::endian::native == std::endian::big) std::reverse(b, b + sizeof(T));
  out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

/// Mitsuba's layout: per mesh, uint16 0x041C, uint16 version, zlib stream;
/// then one offset per mesh (uint64 in version 4, uint32 in 3) and the count.
std::string serializedFile(const std::vector<SerializedMeshData>& meshes, uint16_t version) {
  std::string file;
  std::vector<uint64_t> offsets;
  for (const auto& m : meshes) {
    std::string raw;
    uint32_t flags = (m.normals.empty() ? 0 : 0x1) | (m.uvs.empty() ? 0 : 0x2) | (m.faceNormals ? 0x10 : 0) |
                     (m.doublePrecision ? 0x2000 : 0x1000);
    putLE<uint32_t>(raw, flags);
    if (version == 4) raw.append(m.name.c_str(), m.name.size() + 1);
    putLE<uint64_t>(raw, m.positions.size() / 3);
    putLE<uint64_t>(raw, m.indices.size() / 3);
    for (const auto* array : {&m.positions, &m.normals, &m.uvs})
      for (double v : *array) m.doublePrecision ? putLE<double>(raw, v) : putLE<float>(raw, float(v));
    for (uint32_t i : m.indices) putLE<uint32_t>(raw, i);
    std::string packed(compressBound(uLong(raw.size())), '\0');
    uLongf packedSize = uLongf(packed.size());
    EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(packed.data()), &packedSize,
                        reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()), 6),
              Z_OK);
    packed.resize(packedSize);
    offsets.push_back(file.size());
    putLE<uint16_t>(file, 0x041C);
    putLE<uint16_t>(file, version);
    file += packed;
  }
  for (uint64_t o : offsets) version == 4 ? putLE<uint64_t>(file, o) : putLE<uint32_t>(file, uint32_t(o));
  putLE<uint32_t>(file, uint32_t(meshes.size()));
  return file;
}

SerializedMeshData triangleWithNormals() {
  SerializedMeshData m;
  m.name = "triangle";
  m.positions = {0, 0, 0, 2, 0, 0, 0, 2, 0};
  m.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1};
  m.indices = {0, 1, 2};
  return m;
}

/// A quad at z = 1/3 whose coordinates need double precision to be written exactly.
SerializedMeshData doubleQuadWithUvs() {
  SerializedMeshData m;
  m.name = "quad";
  m.doublePrecision = true;
  double z = 1.0 / 3.0;
  m.positions = {0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z};
  m.uvs = {0, 0, 1, 0, 1, 1, 0, 1};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

}  // namespace

TEST(PlyShape, ReadsAsciiAndBothBinaryByteOrders) {
  for (std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    fs::path file = tempFile("test_" + format + ".ply");
    writeBytes(file, plyFile(format));
    auto mesh = loadMesh("ply", file);
    ASSERT_EQ(mesh->vertexCount(), 5u);
    ASSERT_EQ(mesh->triangleCount(), 3u);  // the quad is fan-triangulated
    EXPECT_NEAR(mesh->surfaceArea(), 1.5f, 1e-6f);
    expectNear(mesh->positions()[4], {0.5f, 0.0f, 1.0f});
    ASSERT_EQ(mesh->normals().size(), 5u);
    expectNear(mesh->normals()[2], {0, 0, 1});
    ASSERT_EQ(mesh->uvs().size(), 5u);
    EXPECT_FLOAT_EQ(mesh->uvs()[2].x, 1.0f);
    EXPECT_FLOAT_EQ(mesh->uvs()[2].y, 1.0f);
    const std::vector<uint32_t> expected = {0, 1, 2, 0, 2, 3, 0, 1, 4};
    EXPECT_EQ(mesh->indices(), expected);
  }
}

TEST(PlyShape, FaceNormalsFlipAndToWorld) {
  fs::path file = tempFile("flip.ply");
  writeBytes(file, plyFile("binary_little_endian"));
  Properties props;
  props.setBool("face_normals", true);
  props.setBool("flip_normals", true);
  props.setTransform("to_world", Transform::scale({2, 2, 2}));
  auto mesh = loadMesh("ply", file, props);
  EXPECT_TRUE(mesh->normals().empty());
  EXPECT_NEAR(mesh->surfaceArea(), 6.0f, 1e-5f);
  PositionSample ps = mesh->samplePosition({0.1f, 0.5f});  // lands on the quad (area fraction 2/3)
  expectNear(ps.n, {0, 0, -1});
}

TEST(PlyShape, TruncatedAndMalformedFilesNameTheFile) {
  std::string binary = plyFile("binary_little_endian");
  fs::path truncated = tempFile("truncated.ply");
  writeBytes(truncated, binary.substr(0, binary.size() - 20));
  std::string message = errorMessageOf([&] { loadMesh("ply", truncated); });
  EXPECT_NE(message.find(truncated.string()), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;

  std::string ascii = plyFile("ascii");
  fs::path bad = tempFile("bad.ply");
  size_t at = ascii.find("end_header\n") + 11;
  writeBytes(bad, ascii.substr(0, at) + "0 zero" + ascii.substr(at + 1));
  message = errorMessageOf([&] { loadMesh("ply", bad); });
  EXPECT_NE(message.find(bad.string() + "\", line 20"), std::string::npos) << message;
  EXPECT_NE(message.find("\"zero\""), std::string::npos) << message;

  fs::path badHeader = tempFile("bad_header.ply");
  writeBytes(badHeader, "ply\nformat ascii 1.0\nelement vertex 3\nproperty quad x\nend_header\n");
  message = errorMessageOf([&] { loadMesh("ply", badHeader); });
  EXPECT_NE(message.find(badHeader.string() + "\", line 4: unknown property type \"quad\""), std::string::npos)
      << message;

  fs::path badIndex = tempFile("bad_index.ply");
  writeBytes(badIndex, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                       "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  message = errorMessageOf([&] { loadMesh("ply", badIndex); });
  EXPECT_NE(message.find(badIndex.string()), std::string::npos) << message;
  EXPECT_NE(message.find("vertex 7"), std::string::npos) << message;

  message = errorMessageOf([&] { loadMesh("ply", tempFile("missing.ply")); });
  EXPECT_NE(message.find("missing.ply"), std::string::npos) << message;
}

TEST(PlyShape, StanfordBunny) {
  fs::path bunny = "/work/shared/meshes/bunny.ply";
  if (!fs::exists(bunny)) GTEST_SKIP() << bunny << " is not present";
  auto mesh = loadMesh("ply", bunny);
  EXPECT_EQ(mesh->vertexCount(), 35947u);
  EXPECT_EQ(mesh->triangleCount(), 69451u);
  EXPECT_TRUE(mesh->bbox().valid());
  EXPECT_GT(mesh->surfaceArea(), 0.0f);
}

TEST(SerializedShape, ReadsEveryMeshOfAVersion4File) {
  fs::path file = tempFile("two.serialized");
  writeBytes(file, serializedFile({triangleWithNormals(), doubleQuadWithUvs()}, 4));

  auto first = loadMesh("serialized", file);
  EXPECT_EQ(first->vertexCount(), 3u);
  EXPECT_EQ(first->triangleCount(), 1u);
  EXPECT_NEAR(first->surfaceArea(), 2.0f, 1e-6f);
  ASSERT_EQ(first->normals().size(), 3u);
  expectNear(first->normals()[1], {0, 0, 1});
  EXPECT_TRUE(first->uvs().empty());

  Properties props;
  props.setInt("shape_index", 1);
  auto second = loadMesh("serialized", file, props);
  EXPECT_EQ(second->vertexCount(), 4u);
  EXPECT_EQ(second->triangleCount(), 2u);
  EXPECT_FLOAT_EQ(second->positions()[2].z, float(1.0 / 3.0));  // double precision read back
  ASSERT_EQ(second->uvs().size(), 4u);
  EXPECT_FLOAT_EQ(second->uvs()[2].x, 1.0f);
  EXPECT_TRUE(second->normals().empty());
  EXPECT_NE(second->toString().find("quad"), std::string::npos);
}

TEST(SerializedShape, Version3AndTheFaceNormalsFlag) {
  SerializedMeshData flat = triangleWithNormals();
  flat.faceNormals = true;
  fs::path file = tempFile("v3.serialized");
  writeBytes(file, serializedFile({doubleQuadWithUvs(), flat}, 3));
  Properties props;
  props.setInt("shape_index", 1);
  auto mesh = loadMesh("serialized", file, props);
  EXPECT_EQ(mesh->triangleCount(), 1u);
  EXPECT_TRUE(mesh->normals().empty());  // the file asks for face normals
  props = Properties();
  props.setInt("shape_index", 0);
  EXPECT_EQ(loadMesh("serialized", file, props)->triangleCount(), 2u);
}

TEST(SerializedShape, BadIndexAndCorruptFilesAreErrors) {
  fs::path file = tempFile("one.serialized");
  std::string bytes = serializedFile({triangleWithNormals(), doubleQuadWithUvs()}, 4);
  writeBytes(file, bytes);
  Properties props;
  props.setInt("shape_index", 2);
  std::string message = errorMessageOf([&] { loadMesh("serialized", file, props); });
  EXPECT_NE(message.find("holds 2 meshes; shape_index 2 is out of range"), std::string::npos) << message;

  // The compressed stream cut short (dictionary kept intact).
  fs::path cut = tempFile("cut.serialized");
  std::string damaged = bytes.substr(0, 20) + bytes.substr(bytes.size() - 20);
  writeBytes(cut, damaged);
  message = errorMessageOf([&] { loadMesh("serialized", cut); });
  EXPECT_NE(message.find(cut.string()), std::string::npos) << message;

  fs::path notSerialized = tempFile("text.serialized");
  writeBytes(notSerialized, "hello world, not a mesh");
  message = errorMessageOf([&] { loadMesh("serialized", notSerialized); });
  EXPECT_NE(message.find("is not a Mitsuba serialized mesh"), std::string::npos) << message;
}
