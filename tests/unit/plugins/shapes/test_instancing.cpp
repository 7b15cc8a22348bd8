// shapegroup + instance: one group (a mesh and an analytic sphere) placed by
// two instances with different transforms; hits must land exactly where the
// transforms put the group, with world-space normals and the group's BSDF.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/render/scene.h>
#include <femto/render/shape_group.h>
#include <femto/xml/loader.h>

#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::shared_ptr<Scene> loadStrict(const std::string& xml) {
  LoadOptions options;
  options.strict = true;
  return loadSceneFromString(xml, std::filesystem::temp_directory_path(), options, "instancing.xml");
}

/// Group: a rectangle (unit square [-1,1]^2 at z = 0, facing +z) and a unit
/// sphere centred at (0, 0, 5), placed by instance A (translate x by 10) and
/// instance B (rotate 90 degrees about x, then translate (-10, 0, 0), scaled 2).
const char* groupScene = R"(<scene version="3.0.0">
  <shape type="shapegroup" id="group">
    <shape type="rectangle"><bsdf type="diffuse" id="grey"><rgb name="reflectance" value="0.3"/></bsdf></shape>
    <shape type="sphere"><point name="center" value="0, 0, 5"/></shape>
  </shape>
  <shape type="instance" id="a">
    <ref id="group"/>
    <transform name="to_world"><translate x="10"/></transform>
  </shape>
  <shape type="instance" id="b">
    <ref id="group"/>
    <transform name="to_world"><scale value="2"/><rotate x="1" angle="90"/><translate x="-10"/></transform>
  </shape>
</scene>)";

void expectNear(const Vec3f& a, const Vec3f& b, float eps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace

TEST(Instancing, HitsThroughTwoInstancesLandWhereTheirTransformsPutTheGroup) {
  auto scene = loadStrict(groupScene);
  SurfaceInteraction si;

  // Instance A: the rectangle is the square around (10, 0, 0) facing +z.
  ASSERT_TRUE(scene->rayIntersect(Ray({10.25f, 0.5f, 3.0f}, {0, 0, -1}), si));
  EXPECT_NEAR(si.t, 3.0f, 1e-5f);
  expectNear(si.p, {10.25f, 0.5f, 0.0f}, 1e-5f);
  expectNear(si.n, {0, 0, 1}, 1e-6f);
  expectNear(si.sh.n, {0, 0, 1}, 1e-6f);
  expectNear(si.wi, {0, 0, 1}, 1e-6f);
  ASSERT_NE(si.shape, nullptr);
  EXPECT_NE(si.shape->asMesh(), nullptr);  // the group's rectangle, with its BSDF
  EXPECT_EQ(si.bsdf(), si.shape->bsdf());
  // Its sphere is the unit sphere at (10, 0, 5); from +x the hit is at x = 11.
  ASSERT_TRUE(scene->rayIntersect(Ray({20.0f, 0.0f, 5.0f}, {-1, 0, 0}), si));
  EXPECT_NEAR(si.t, 9.0f, 1e-5f);
  expectNear(si.p, {11.0f, 0.0f, 5.0f}, 1e-5f);
  expectNear(si.n, {1, 0, 0}, 1e-5f);
  EXPECT_EQ(si.shape->asMesh(), nullptr);

  // Instance B: scale 2, then rotate +90 about x (z -> -y, y -> z), then move
  // to x = -10. The rectangle becomes the 4x4 square in the plane y = 0
  // facing -y; the sphere has radius 2 and centre (-10, -10, 0).
  ASSERT_TRUE(scene->rayIntersect(Ray({-9.0f, -4.0f, 1.5f}, {0, 1, 0}), si));
  EXPECT_NEAR(si.t, 4.0f, 1e-5f);
  expectNear(si.p, {-9.0f, 0.0f, 1.5f}, 1e-5f);
  expectNear(si.n, {0, -1, 0}, 1e-5f);
  expectNear(si.sh.n, {0, -1, 0}, 1e-5f);
  // Outside the scaled square (|z| > 2) the ray misses instance B's rectangle.
  EXPECT_FALSE(scene->rayIntersect(Ray({-9.0f, -4.0f, 2.5f}, {0, 1, 0}), si));
  ASSERT_TRUE(scene->rayIntersect(Ray({-10.0f, -10.0f, 10.0f}, {0, 0, -1}), si));
  EXPECT_NEAR(si.t, 8.0f, 1e-5f);
  expectNear(si.p, {-10.0f, -10.0f, 2.0f}, 1e-5f);
  expectNear(si.n, {0, 0, 1}, 1e-5f);
  // The shading frame stays orthonormal after the transform.
  EXPECT_NEAR(dot(si.sh.s, si.sh.n), 0.0f, 1e-5f);
  EXPECT_NEAR(length(si.sh.s), 1.0f, 1e-5f);
  EXPECT_NEAR(length(si.sh.t), 1.0f, 1e-5f);

  // Shadow rays and hit distances see instances too; the group itself is not in the scene.
  EXPECT_TRUE(scene->rayTest(Ray({10.0f, 0.0f, 3.0f}, {0, 0, -1}, 0.0f, 10.0f)));
  EXPECT_FALSE(scene->rayTest(Ray({0.0f, 0.0f, 3.0f}, {0, 0, -1}, 0.0f, 10.0f)));
  EXPECT_NEAR(scene->rayHitDistance(Ray({10.0f, 0.0f, 3.0f}, {0, 0, -1})), 3.0f, 1e-5f);
  EXPECT_EQ(scene->rayHitDistance(Ray({0.0f, 0.0f, 3.0f}, {0, 0, -1})), Infinity);
  // Bounds: the two instances, not the group at the origin on its own.
  EXPECT_NEAR(scene->bbox().max.x, 11.0f, 1e-4f);
  EXPECT_NEAR(scene->bbox().min.x, -12.0f, 1e-4f);
}

TEST(Instancing, NonUniformScaleKeepsNormalsPerpendicularToTheSurface) {
  // Sphere scaled 3x along x: an ellipsoid. At the point (3/sqrt2, 0, 1/sqrt2)
  // (ellipsoid x^2/9 + z^2 = 1) the normal is along (x/9, 0, z).
  auto scene = loadStrict(R"(<scene version="3.0.0">
    <shape type="shapegroup" id="g"><shape type="sphere"/></shape>
    <shape type="instance"><ref id="g"/><transform name="to_world"><scale x="3"/></transform></shape>
  </scene>)");
  float x = 3.0f / std::sqrt(2.0f), z = 1.0f / std::sqrt(2.0f);
  SurfaceInteraction si;
  ASSERT_TRUE(scene->rayIntersect(Ray({x, 0.0f, 5.0f}, {0, 0, -1}), si));
  expectNear(si.p, {x, 0.0f, z}, 1e-4f);
  expectNear(si.n, normalize(Vec3f(x / 9.0f, 0.0f, z)), 1e-4f);
}

TEST(Instancing, InstancedShapesCannotBeAreaEmitters) {
  std::string message = errorMessageOf([] {
    loadStrict(R"(<scene version="3.0.0">
  <shape type="shapegroup" id="g">
    <shape type="sphere"><emitter type="area"><rgb name="radiance" value="1"/></emitter></shape>
  </shape>
</scene>)");
  });
  EXPECT_NE(message.find("instancing.xml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("area emitter"), std::string::npos) << message;

  message = errorMessageOf([] {
    loadStrict(R"(<scene version="3.0.0">
  <shape type="shapegroup" id="g"><shape type="sphere"/></shape>
  <shape type="instance"><ref id="g"/><emitter type="area"><rgb name="radiance" value="1"/></emitter></shape>
</scene>)");
  });
  EXPECT_NE(message.find("instancing.xml:3"), std::string::npos) << message;
  EXPECT_NE(message.find("area emitter"), std::string::npos) << message;
}

TEST(Instancing, InstanceMustReferenceAShapeGroup) {
  std::string message = errorMessageOf([] {
    loadStrict(R"(<scene version="3.0.0">
  <shape type="sphere" id="s"/>
  <shape type="instance"><ref id="s"/></shape>
</scene>)");
  });
  EXPECT_NE(message.find("instancing.xml:3"), std::string::npos) << message;
  EXPECT_NE(message.find("shapegroup"), std::string::npos) << message;

  message = errorMessageOf([] {
    loadStrict(R"(<scene version="3.0.0">
  <shape type="shapegroup" id="g"><shape type="sphere"/></shape>
  <shape type="shapegroup" id="h"><shape type="instance"><ref id="g"/></shape></shape>
</scene>)");
  });
  EXPECT_NE(message.find("one level of instancing"), std::string::npos) << message;
}

TEST(Instancing, TheSceneSeesMediaAndPassThroughShapesInsideShapeGroups) {
  // Time gating bounds a connection's OPL by the scene's largest refractive
  // index (Scene::largestMediumEta), and connections cross pass-through
  // shapes only when the scene knows it has some (hasPassThroughShapes): a
  // medium or a null-BSDF shape named only inside a group, reached through an
  // instance, must count (the group itself is not among the scene's shapes).
  auto scene = loadStrict(R"(<scene version="3.0.0">
  <medium type="homogeneous" id="water"><float name="sigma_t" value="1"/><float name="eta" value="1.33"/></medium>
  <medium type="homogeneous" id="air"><float name="sigma_t" value="1"/><float name="eta" value="1.1"/></medium>
  <shape type="shapegroup" id="group">
    <shape type="sphere"><bsdf type="null"/><ref name="interior" id="water"/></shape>
  </shape>
  <shape type="instance"><ref id="group"/></shape>
  <shape type="rectangle"><bsdf type="null"/><ref name="exterior" id="air"/>
    <transform name="to_world"><translate z="-5"/></transform></shape>
</scene>)");
  EXPECT_FLOAT_EQ(scene->largestMediumEta(), 1.33f);
  auto plain = loadStrict(R"(<scene version="3.0.0"><shape type="sphere"/></scene>)");
  EXPECT_FLOAT_EQ(plain->largestMediumEta(), 1.0f);
  EXPECT_FALSE(plain->hasPassThroughShapes());
  auto instancedBoundary = loadStrict(R"(<scene version="3.0.0">
  <shape type="shapegroup" id="group"><shape type="sphere"><bsdf type="null"/></shape></shape>
  <shape type="instance"><ref id="group"/></shape>
</scene>)");
  EXPECT_TRUE(instancedBoundary->hasPassThroughShapes());
}

