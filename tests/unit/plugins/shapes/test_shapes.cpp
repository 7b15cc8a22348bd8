// Shape plugins: rectangle, cube, obj (triangle meshes) and the analytic sphere.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <femto/math/pcg32.h>
#include <femto/render/mesh.h>
#include <femto/xml/loader.h>

#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::shared_ptr<Shape> makeShape(const std::string& type, Properties props = {}) {
  props.setPluginName(type);
  return createPlugin<Shape>(ObjectKind::Shape, props);
}

Normal3f triangleNormal(const TriangleMesh& mesh, size_t i) {
  const auto& p = mesh.positions();
  const auto& idx = mesh.indices();
  return normalize(cross(p[idx[3 * i + 1]] - p[idx[3 * i]], p[idx[3 * i + 2]] - p[idx[3 * i]]));
}

Point3f triangleCentroid(const TriangleMesh& mesh, size_t i) {
  const auto& p = mesh.positions();
  const auto& idx = mesh.indices();
  return (p[idx[3 * i]] + p[idx[3 * i + 1]] + p[idx[3 * i + 2]]) / 3.0f;
}

void expectNear(const Vec3f& a, const Vec3f& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace

TEST(RectangleShape, IsTheUnitSquareFacingPlusZ) {
  auto shape = makeShape("rectangle");
  const TriangleMesh* mesh = shape->asMesh();
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->triangleCount(), 2u);
  EXPECT_FLOAT_EQ(shape->surfaceArea(), 4.0f);
  for (size_t i = 0; i < 2; ++i) expectNear(triangleNormal(*mesh, i), {0, 0, 1});
  expectNear(shape->bbox().min, {-1, -1, 0});
  expectNear(shape->bbox().max, {1, 1, 0});
  PositionSample ps = shape->samplePosition({0.3f, 0.8f});
  expectNear(ps.n, {0, 0, 1});
  EXPECT_FLOAT_EQ(ps.pdf, 0.25f);
}

TEST(RectangleShape, ToWorldAndFlipNormals) {
  Properties props;
  props.setTransform("to_world", Transform::translate({0, 2, 0}) * Transform::rotate({1, 0, 0}, 90) *
                                     Transform::scale({3, 3, 3}));
  props.setBool("flip_normals", true);
  auto shape = makeShape("rectangle", props);
  EXPECT_NEAR(shape->surfaceArea(), 36.0f, 1e-4f);
  // rotate +90 about x maps +z to -y; flipped, the normal is +y.
  PositionSample ps = shape->samplePosition({0.5f, 0.5f});
  expectNear(ps.n, {0, 1, 0});
  EXPECT_NEAR(ps.p.y, 2.0f, 1e-5f);
}

TEST(CubeShape, HasTwelveOutwardFacingTriangles) {
  auto shape = makeShape("cube");
  const TriangleMesh* mesh = shape->asMesh();
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->triangleCount(), 12u);
  EXPECT_NEAR(shape->surfaceArea(), 24.0f, 1e-5f);
  for (size_t i = 0; i < 12; ++i) {
    Normal3f n = triangleNormal(*mesh, i);
    Point3f c = triangleCentroid(*mesh, i);
    // Centroids lie on a face: the normal is that face's axis, pointing away from the centre.
    EXPECT_NEAR(maxComponent(abs(n)), 1.0f, 1e-6f);
    EXPECT_NEAR(dot(n, c), 1.0f, 1e-5f) << "triangle " << i;
  }
  ASSERT_EQ(mesh->normals().size(), mesh->vertexCount());
  for (size_t v = 0; v < mesh->vertexCount(); ++v) {
    // Vertex normals are the face normals (flat faces).
    EXPECT_NEAR(dot(mesh->normals()[v], mesh->positions()[v]), 1.0f, 1e-5f);
    EXPECT_GE(mesh->uvs()[v].x, 0.0f);
    EXPECT_LE(mesh->uvs()[v].x, 1.0f);
  }
}

TEST(SphereShape, IntersectsFromOutsideAndInside) {
  Properties props;
  props.setPoint("center", {1, 2, 3});
  props.setFloat("radius", 0.5);
  auto shape = makeShape("sphere", props);
  float t = 0;
  Point2f uv;
  ASSERT_TRUE(shape->intersect(Ray({1, 2, -2}, {0, 0, 1}), t, uv));
  EXPECT_NEAR(t, 4.5f, 1e-5f);
  ASSERT_TRUE(shape->intersect(Ray({1, 2, 3}, {0, 1, 0}), t, uv));  // from the centre
  EXPECT_NEAR(t, 0.5f, 1e-6f);
  EXPECT_FALSE(shape->intersect(Ray({1, 2, -2}, {0, 0, -1}), t, uv));       // pointing away
  EXPECT_FALSE(shape->intersect(Ray({1, 2.6f, -2}, {0, 0, 1}), t, uv));     // passes above
  EXPECT_FALSE(shape->intersect(Ray({1, 2, -2}, {0, 0, 1}, 0, 4.0f), t, uv));  // tmax before the hit
  ASSERT_TRUE(shape->intersect(Ray({1, 2, -2}, {0, 0, 1}, 4.6f, Infinity), t, uv));  // tmin past the near hit
  EXPECT_NEAR(t, 5.5f, 1e-5f);
}

TEST(SphereShape, IntersectionIsAccurateForSmallFarSpheres) {
  // The naive quadratic loses all digits of the discriminant here
  // (Ray Tracing Gems ch. 7); the robust form keeps the hit on the surface.
  Properties props;
  props.setPoint("center", {0, 0, 10000});
  props.setFloat("radius", 0.01);
  auto shape = makeShape("sphere", props);
  float t = 0;
  Point2f uv;
  ASSERT_TRUE(shape->intersect(Ray({0, 0.005f, 0}, {0, 0, 1}), t, uv));
  double expected = 10000.0 - std::sqrt(0.01 * 0.01 - 0.005 * 0.005);
  EXPECT_NEAR(t, expected, 2e-3);
}

TEST(SphereShape, InteractionNormalsAndUvs) {
  Properties props;
  props.setFloat("radius", 2.0);
  auto shape = makeShape("sphere", props);
  Ray ray({0, 0, 5}, {0, 0, -1});
  float t;
  Point2f uv;
  ASSERT_TRUE(shape->intersect(ray, t, uv));
  SurfaceInteraction si;
  shape->computeInteraction(ray, t, 0, uv, si);
  expectNear(si.p, {0, 0, 2});
  expectNear(si.n, {0, 0, 1});
  expectNear(si.sh.n, {0, 0, 1});
  EXPECT_NEAR(si.uv.y, 0.0f, 1e-4f);  // theta = 0 at the +z pole

  props = Properties();
  props.setBool("flip_normals", true);
  auto inward = makeShape("sphere", props);
  Ray fromInside({0, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(inward->intersect(fromInside, t, uv));
  inward->computeInteraction(fromInside, t, 0, uv, si);
  expectNear(si.n, {-1, 0, 0});
  EXPECT_NEAR(si.uv.x, 0.0f, 1e-5f);
  EXPECT_NEAR(si.uv.y, 0.5f, 1e-5f);
}

TEST(SphereShape, ToWorldScaleFoldsIntoTheRadius) {
  Properties props;
  props.setTransform("to_world", Transform::translate({0, 0, 1}) * Transform::scale({3, 3, 3}));
  auto shape = makeShape("sphere", props);
  EXPECT_NEAR(shape->surfaceArea(), 4.0f * Pi * 9.0f, 1e-3f);
  expectNear(shape->bbox().min, {-3, -3, -2});
  PCG32 rng;
  for (int i = 0; i < 100; ++i) {
    PositionSample ps = shape->samplePosition({rng.nextFloat(), rng.nextFloat()});
    EXPECT_NEAR(distance(ps.p, Point3f(0, 0, 1)), 3.0f, 1e-5f);
    EXPECT_NEAR(dot(ps.n, (ps.p - Point3f(0, 0, 1)) / 3.0f), 1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(ps.pdf, 1.0f / shape->surfaceArea());
  }
}

TEST(SphereShape, RejectsNonUniformScaleAndBadRadius) {
  Properties props("sphere");
  props.setTransform("to_world", Transform::scale({1, 2, 1}), {"scene.xml", 7});
  EXPECT_NE(errorMessageOf([&] { makeShape("sphere", props); }).find("scene.xml:7"), std::string::npos);
  Properties bad("sphere");
  bad.setFloat("radius", -1.0, {"scene.xml", 9});
  EXPECT_NE(errorMessageOf([&] { makeShape("sphere", bad); }).find("radius"), std::string::npos);
}

class ObjShape : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("femto-obj-test-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  std::filesystem::path dir_;
};

TEST_F(ObjShape, TriangulatesPolygonsAndKeepsNormalsAndUvs) {
  auto file = write("quad.obj",
                    "# unit quad in z = 0, as one polygon\n"
                    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                    "vn 0 0 1\n"
                    "f 1/1/1 2/2/1 3/3/1 4/4/1\n");
  Properties props;
  props.setString("filename", file.string());
  auto shape = makeShape("obj", props);
  const TriangleMesh* mesh = shape->asMesh();
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->triangleCount(), 2u);
  EXPECT_EQ(mesh->vertexCount(), 4u);
  EXPECT_EQ(mesh->normals().size(), 4u);
  EXPECT_EQ(mesh->uvs().size(), 4u);
  EXPECT_FLOAT_EQ(shape->surfaceArea(), 4.0f);
  for (size_t i = 0; i < 2; ++i) expectNear(triangleNormal(*mesh, i), {0, 0, 1});
}

TEST_F(ObjShape, TexCoordsAreFlippedVerticallyByDefaultAsInMitsuba) {
  auto file = write("uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.1\nvt 0.5 0.2\nvt 0.75 0.3\nf 1/1 2/2 3/3\n");
  for (bool flip : {true, false}) {
    Properties props;
    props.setString("filename", file.string());
    if (!flip) props.setBool("flip_tex_coords", false);
    auto shape = makeShape("obj", props);
    const auto& uvs = shape->asMesh()->uvs();
    ASSERT_EQ(uvs.size(), 3u);
    const float v[3] = {0.1f, 0.2f, 0.3f};
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_FLOAT_EQ(uvs[i].x, 0.25f * float(i + 1));
      EXPECT_FLOAT_EQ(uvs[i].y, flip ? 1.0f - v[i] : v[i]);
    }
  }
}

TEST_F(ObjShape, FaceNormalsDropsVertexNormals) {
  auto file = write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
  Properties props;
  props.setString("filename", file.string());
  props.setBool("face_normals", true);
  auto shape = makeShape("obj", props);
  EXPECT_TRUE(shape->asMesh()->normals().empty());
  EXPECT_TRUE(shape->asMesh()->uvs().empty());
  EXPECT_FLOAT_EQ(shape->surfaceArea(), 0.5f);
}

TEST_F(ObjShape, MissingFileNamesTheFileAndTheSceneLine) {
  Properties props("obj");
  props.setLocation({"scene.xml", 3});
  props.setString("filename", (dir_ / "nope.obj").string(), {"scene.xml", 4});
  std::string message = errorMessageOf([&] { makeShape("obj", props); });
  EXPECT_NE(message.find("scene.xml:4"), std::string::npos) << message;
  EXPECT_NE(message.find("nope.obj"), std::string::npos) << message;
}

TEST_F(ObjShape, AFileWithoutFacesIsAnError) {
  auto file = write("empty.obj", "v 0 0 0\nv 1 0 0\n");
  Properties props("obj");
  props.setString("filename", file.string(), {"scene.xml", 5});
  std::string message = errorMessageOf([&] { makeShape("obj", props); });
  EXPECT_NE(message.find("no faces"), std::string::npos) << message;
  EXPECT_NE(message.find("scene.xml:5"), std::string::npos) << message;
}

TEST_F(ObjShape, LoadsFromXmlWithAPathRelativeToTheScene) {
  write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  LoadOptions options;
  options.strict = true;
  auto shape = std::dynamic_pointer_cast<Shape>(loadObjectFromString(
      R"(<shape type="obj" version="3.0.0"><string name="filename" value="tri.obj"/>
         <transform name="to_world"><scale value="2"/></transform></shape>)",
      dir_, options));
  ASSERT_NE(shape, nullptr);
  EXPECT_FLOAT_EQ(shape->surfaceArea(), 2.0f);
}

TEST_F(ObjShape, ADirectoryIsNotAnObjFile) {
  std::filesystem::create_directories(dir_ / "folder.obj");
  Properties props("obj");
  props.setString("filename", (dir_ / "folder.obj").string(), {"scene.xml", 6});
  std::string message = errorMessageOf([&] { makeShape("obj", props); });
  EXPECT_NE(message.find("scene.xml:6"), std::string::npos) << message;
  EXPECT_NE(message.find("folder.obj"), std::string::npos) << message;
}
