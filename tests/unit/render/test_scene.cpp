// Scene: Embree intersection of triangle meshes and analytic (user geometry)
// shapes, shadow rays, emitter picking, default children.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <femto/render/bsdf.h>
#include <femto/render/mesh.h>
#include <femto/render/scene.h>

#include "render_test_util.h"

namespace femto {
namespace {

/// Minimal analytic sphere, to exercise the user-geometry path of the core.
class TestSphere final : public Shape {
 public:
  TestSphere(const Properties& props, Point3f c, float r) : Shape(props), c_(c), r_(r) {}
  BoundingBox3f bbox() const override { return {c_ - Vec3f(r_), c_ + Vec3f(r_)}; }
  float surfaceArea() const override { return 4 * Pi * r_ * r_; }
  PositionSample samplePosition(const Point2f&) const override { return {}; }
  bool intersect(const Ray& ray, float& t, Point2f& uv) const override {
    Vec3f f = ray.o - c_;
    float b = dot(f, ray.d), c = dot(f, f) - r_ * r_, disc = b * b - c;  // unit direction
    if (disc < 0) return false;
    float s = std::sqrt(disc);
    for (float cand : {-b - s, -b + s})
      if (cand > ray.tmin && cand < ray.tmax) {
        t = cand;
        uv = Point2f(0.25f, 0.75f);
        return true;
      }
    return false;
  }
  void computeInteraction(const Ray& ray, float t, uint32_t, const Point2f& uv, SurfaceInteraction& si) const override {
    si.p = ray(t);
    si.n = normalize(si.p - c_);
    si.sh = Frame(si.n);
    si.uv = uv;
  }

 private:
  Point3f c_;
  float r_;
};

/// The square [-1, 1]^2 at z = 0 as two triangles, wound so the normal is +z.
std::shared_ptr<TriangleMesh> square(const Transform& toWorld, bool flip = false, Properties props = Properties("test_mesh")) {
  auto mesh = std::make_shared<TriangleMesh>(props);
  mesh->setGeometry({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, {0, 1, 2, 0, 2, 3}, {}, {}, toWorld, flip, false);
  return mesh;
}

/// Emitter that records what it was asked; returns its weight as radiance / pdf.
class TestEmitter final : public Emitter {
 public:
  explicit TestEmitter(const Properties& props) : Emitter(props), value_(samplingWeight()) {}
  Color3f sampleDirection(const Point3f& ref, const Point2f& u, DirectionSample& ds) const override {
    lastU = u;
    ++calls;
    ds.p = ref + Vec3f(0, 0, 1);
    ds.d = Vec3f(0, 0, 1);
    ds.dist = 1;
    ds.pdf = 0.5f;
    return Color3f(value_);
  }
  float pdfDirection(const Point3f&, const DirectionSample&) const override { return 0.5f; }
  bool isDelta() const override { return false; }
  mutable Point2f lastU;
  mutable int calls = 0;

 private:
  float value_;
};

std::shared_ptr<Scene> makeScene(const std::vector<std::shared_ptr<Object>>& children) {
  Properties props("scene");
  int i = 0;
  for (const auto& c : children) props.setObject("_arg_" + std::to_string(i++), c);
  return std::make_shared<Scene>(props);
}

TEST(Scene, IntersectsTriangleMeshAtExactDistance) {
  auto mesh = square(Transform::translate({0, 0, 5}) * Transform::rotate({1, 0, 0}, 180));  // faces -z
  auto scene = makeScene({mesh});
  SurfaceInteraction si;
  ASSERT_TRUE(scene->rayIntersect(Ray({0.25f, -0.5f, 0}, {0, 0, 1}), si));
  EXPECT_FLOAT_EQ(si.t, 5.0f);
  EXPECT_EQ(si.shape, mesh.get());
  EXPECT_NEAR(si.p.x, 0.25f, 1e-6f);
  EXPECT_NEAR(si.p.y, -0.5f, 1e-6f);
  EXPECT_NEAR(si.p.z, 5.0f, 1e-6f);
  EXPECT_NEAR(si.n.z, -1.0f, 1e-6f);  // rotated with the mesh: toward the ray origin
  EXPECT_NEAR(si.wi.z, 1.0f, 1e-6f);  // wi is local: toward the viewer along the normal
  EXPECT_FALSE(scene->rayIntersect(Ray({1.5f, 0, 0}, {0, 0, 1}), si));
  EXPECT_FALSE(scene->rayIntersect(Ray({0, 0, 0}, {0, 0, 1}, 0, 4.9f), si));
  EXPECT_TRUE(scene->rayTest(Ray({0, 0, 0}, {0, 0, 1}, 0, 5.1f)));
  EXPECT_FALSE(scene->rayTest(Ray({0, 0, 0}, {0, 0, 1}, 0, 4.9f)));
  EXPECT_FALSE(scene->rayTest(Ray({0, 0, 0}, {0, 0, -1})));
  // A shape without a BSDF gets Mitsuba's default diffuse one.
  ASSERT_NE(mesh->bsdf(), nullptr);
  EXPECT_TRUE(mesh->bsdf()->flags() & BSDFFlags::DiffuseReflection);
}

TEST(Scene, MeshGeometryFlipAndSampling) {
  auto plain = square(Transform::scale({2, 3, 1}));
  EXPECT_FLOAT_EQ(plain->surfaceArea(), 24.0f);
  EXPECT_EQ(plain->bbox().max, Point3f(2, 3, 0));
  auto flipped = square(Transform(), true);
  SurfaceInteraction a, b;
  Ray down({0.1f, 0.2f, 1}, {0, 0, -1});
  plain->computeInteraction(down, 1, 0, {0.2f, 0.3f}, a);
  flipped->computeInteraction(down, 1, 0, {0.2f, 0.3f}, b);
  EXPECT_NEAR(a.n.z, 1.0f, 1e-6f);
  EXPECT_NEAR(b.n.z, -1.0f, 1e-6f);
  EXPECT_NEAR(b.sh.n.z, -1.0f, 1e-6f);
  // Area sampling: every sample on the surface with density 1 / area.
  for (float u : {0.0f, 0.3f, 0.5f, 0.99999f}) {
    PositionSample ps = plain->samplePosition({u, 0.7f});
    EXPECT_FLOAT_EQ(ps.pdf, 1.0f / 24.0f);
    EXPECT_EQ(ps.p.z, 0.0f);
    EXPECT_LE(std::abs(ps.p.x), 2.0f + 1e-6f);
    EXPECT_LE(std::abs(ps.p.y), 3.0f + 1e-6f);
  }
}

TEST(Scene, InterpolatesShadingNormalsAndUvs) {
  auto mesh = std::make_shared<TriangleMesh>(Properties("test_mesh"));
  Normal3f n0 = normalize(Vec3f(1, 0, 1)), n1(0, 0, 1), n2(0, 0, 1);
  mesh->setGeometry({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}, {n0, n1, n2}, {{0, 0}, {1, 0}, {0, 1}}, Transform(),
                    false, false);
  SurfaceInteraction si;
  mesh->computeInteraction(Ray({0, 0, 1}, {0, 0, -1}), 1, 0, {0.25f, 0.5f}, si);
  Vec3f expected = normalize(n0 * 0.25f + n1 * 0.25f + n2 * 0.5f);
  EXPECT_NEAR(si.sh.n.x, expected.x, 1e-6f);
  EXPECT_NEAR(si.sh.n.z, expected.z, 1e-6f);
  EXPECT_NEAR(si.n.z, 1.0f, 1e-6f);  // geometric normal from the winding
  EXPECT_FLOAT_EQ(si.uv.x, 0.25f);
  EXPECT_FLOAT_EQ(si.uv.y, 0.5f);
  // The tangent follows dp/du (here +x rotated into the plane of the shading normal).
  EXPECT_NEAR(dot(si.sh.s, si.sh.n), 0.0f, 1e-6f);
  EXPECT_NEAR(dot(si.sh.t, si.sh.n), 0.0f, 1e-6f);
  EXPECT_NEAR(si.sh.s.y, 0.0f, 1e-6f);
  EXPECT_GT(si.sh.s.x, 0.5f);
  EXPECT_NEAR(si.sh.t.y, 1.0f, 1e-6f);  // right-handed: s x t = n
  EXPECT_THROW(mesh->setGeometry({{0, 0, 0}}, {0, 1, 2}, {}, {}, Transform(), false, false), Error);
}

TEST(Scene, IntersectsAnalyticShapeThroughUserGeometry) {
  auto sphere = std::make_shared<TestSphere>(Properties("test_sphere"), Point3f(3, 0, 0), 1.0f);
  auto mesh = square(Transform::translate({0, 0, 5}));
  auto scene = makeScene({mesh, sphere});
  SurfaceInteraction si;
  ASSERT_TRUE(scene->rayIntersect(Ray({0, 0, 0}, {1, 0, 0}), si));
  EXPECT_EQ(si.t, 2.0f);
  EXPECT_EQ(si.shape, sphere.get());
  EXPECT_EQ(si.uv, Point2f(0.25f, 0.75f));  // passed from intersect() to computeInteraction()
  EXPECT_NEAR(si.n.x, -1.0f, 1e-6f);
  // From inside, the far side; tmin excludes the near root.
  ASSERT_TRUE(scene->rayIntersect(Ray({3, 0, 0}, {1, 0, 0}), si));
  EXPECT_EQ(si.t, 1.0f);
  EXPECT_TRUE(scene->rayTest(Ray({0, 0, 0}, {1, 0, 0}, 0, 2.5f)));
  EXPECT_FALSE(scene->rayTest(Ray({0, 0, 0}, {1, 0, 0}, 0, 1.5f)));
  EXPECT_FALSE(scene->rayTest(Ray({0, 0, 0}, {-1, 0, 0})));
  // The nearest of both kinds wins.
  ASSERT_TRUE(scene->rayIntersect(Ray({3, 0, 10}, {0, 0, -1}), si));
  EXPECT_EQ(si.shape, sphere.get());
  EXPECT_EQ(si.t, 9.0f);
  EXPECT_EQ(scene->shapes().size(), 2u);
  EXPECT_TRUE(scene->bbox().contains(Point3f(4, 0, 0)));
}

TEST(Scene, SpawnedRaysLeaveTheSurfaceFarFromTheOrigin) {
  // Far from the origin the hit point's rounding error is large; the offset
  // must scale with it or the spawned ray re-hits its own surface.
  auto mesh = square(Transform::translate({3000, -2000, 1000}) * Transform::scale({10, 10, 1}));
  auto scene = makeScene({mesh});
  SurfaceInteraction si;
  for (float x : {-7.3f, 0.1f, 4.9f}) {
    ASSERT_TRUE(scene->rayIntersect(Ray({3000 + x, -2000.3f, 1003}, normalize(Vec3f(0.1f, 0.2f, -1))), si));
    SurfaceInteraction again;
    EXPECT_FALSE(scene->rayIntersect(si.spawnRay(normalize(Vec3f(0.3f, 0.1f, 1))), again));  // leaves upward
    EXPECT_FALSE(scene->rayTest(si.spawnRayTo(si.p + Vec3f(-0.5f, 0.2f, 2))));
    Ray through = si.spawnRay(Vec3f(0, 0, -1));  // crosses to the other side
    EXPECT_LT(through.o.z, 1000.0f);
    EXPECT_FALSE(scene->rayIntersect(through, again));
  }
  EXPECT_EQ(si.Le(Vec3f(0, 0, 1)), Color3f(0.0f));  // not an emitter
}

TEST(Scene, PicksEmittersProportionallyToSamplingWeight) {
  std::vector<std::shared_ptr<TestEmitter>> emitters;
  std::vector<std::shared_ptr<Object>> children;
  for (float w : {1.0f, 2.0f, 5.0f}) {
    Properties p("test_emitter");
    p.setFloat("sampling_weight", w);
    emitters.push_back(std::make_shared<TestEmitter>(p));
    children.push_back(emitters.back());
  }
  auto scene = makeScene(children);
  ASSERT_EQ(scene->emitters().size(), 3u);
  EXPECT_FLOAT_EQ(scene->emitterPickProbability(emitters[0].get()), 1.0f / 8);
  EXPECT_FLOAT_EQ(scene->emitterPickProbability(emitters[2].get()), 5.0f / 8);

  // A uniform grid over u.x picks each emitter in proportion to its weight,
  // and reports radiance / (pick * pdf) and pdf * pick.
  const int n = 800;
  SurfaceInteraction ref;
  ref.p = Point3f(0);
  ref.n = Normal3f(0, 0, 1);
  for (int i = 0; i < n; ++i) {
    DirectionSample ds;
    int before[3] = {emitters[0]->calls, emitters[1]->calls, emitters[2]->calls};
    Color3f v = scene->sampleEmitterDirection(ref, {(i + 0.5f) / n, 0.3f}, ds, false);
    int k = 0;
    while (k < 3 && emitters[k]->calls == before[k]) ++k;
    ASSERT_LT(k, 3);
    float pick = scene->emitterPickProbability(emitters[k].get());
    EXPECT_FLOAT_EQ(v.r, emitters[k]->samplingWeight() / pick);  // the emitter already divided by its pdf
    EXPECT_FLOAT_EQ(ds.pdf, 0.5f * pick);
    EXPECT_GE(emitters[k]->lastU.x, 0.0f);  // the reused sample stays in [0, 1)
    EXPECT_LT(emitters[k]->lastU.x, 1.0f);
  }
  EXPECT_EQ(emitters[0]->calls, 100);
  EXPECT_EQ(emitters[1]->calls, 200);
  EXPECT_EQ(emitters[2]->calls, 500);
  DirectionSample ds;
  EXPECT_FLOAT_EQ(scene->pdfEmitterDirection(Point3f(0), ds, emitters[1].get()), 0.5f * 2.0f / 8);
}

TEST(Scene, CollectsShapeEmittersOnce) {
  struct Attachable final : Emitter {
    explicit Attachable(const Properties& p) : Emitter(p) {}
    Color3f sampleDirection(const Point3f&, const Point2f&, DirectionSample&) const override { return {}; }
    float pdfDirection(const Point3f&, const DirectionSample&) const override { return 0; }
    bool isDelta() const override { return false; }
    void setShape(const Shape* s) override { shape = s; }
    const Shape* shape = nullptr;
  };
  auto emitter = std::make_shared<Attachable>(Properties("test_area"));
  Properties shapeProps("test_mesh");
  shapeProps.setObject("emitter", emitter);
  auto mesh = square(Transform(), false, shapeProps);
  EXPECT_EQ(emitter->shape, mesh.get());  // the Shape constructor attaches it
  EXPECT_EQ(mesh->emitter(), emitter.get());
  auto scene = makeScene({mesh, emitter});  // also listed at top level
  ASSERT_EQ(scene->emitters().size(), 1u);
  EXPECT_FLOAT_EQ(scene->emitterPickProbability(emitter.get()), 1.0f);
}

TEST(Scene, ShadowRayToEmitterIsBlocked) {
  Properties p("test_emitter");
  auto emitter = std::make_shared<TestEmitter>(p);
  auto blocker = square(Transform::translate({0, 0, 0.5f}));
  auto scene = makeScene({emitter, blocker});
  SurfaceInteraction ref;
  ref.p = Point3f(0);
  ref.n = Normal3f(0, 0, 1);
  DirectionSample ds;
  EXPECT_TRUE(scene->sampleEmitterDirection(ref, {0.5f, 0.5f}, ds, true).isBlack());
  EXPECT_FALSE(scene->sampleEmitterDirection(ref, {0.5f, 0.5f}, ds, false).isBlack());
}

TEST(Emitter, BaseClassRefusesWhatItCannotDo) {
  Properties p("test_emitter");
  TestEmitter e(p);
  Ray ray;
  EXPECT_THROW(e.sampleRay({0, 0}, {0, 0}, ray), Error);
  EXPECT_THROW(e.power(), Error);
  EXPECT_TRUE(e.eval(SurfaceInteraction(), Vec3f(0, 0, 1)).isBlack());
  // Only area emitters may sit on a shape.
  Properties shapeProps("test_mesh");
  shapeProps.setObject("_arg_0", std::make_shared<TestEmitter>(p));
  EXPECT_THROW(TriangleMesh{shapeProps}, Error);
  Properties bad("test_emitter");
  bad.setFloat("sampling_weight", -1);
  EXPECT_THROW(TestEmitter{bad}, Error);
}

}  // namespace
}  // namespace femto
