// Vector operations, shading frames, the PCG32 generator and bounding boxes.
#include <gtest/gtest.h>

#include <set>

#include <femto/math/bbox.h>
#include <femto/math/frame.h>
#include <femto/math/pcg32.h>
#include <femto/math/vector.h>
#include <femto/math/warp.h>

using namespace femto;

TEST(Vector, ArithmeticAndProducts) {
  Vec3f a(1, 2, 3), b(4, -5, 6);
  EXPECT_EQ(a + b, Vec3f(5, -3, 9));
  EXPECT_EQ(a - b, Vec3f(-3, 7, -3));
  EXPECT_EQ(a * 2.0f, Vec3f(2, 4, 6));
  EXPECT_EQ(2.0f * a, Vec3f(2, 4, 6));
  EXPECT_FLOAT_EQ(dot(a, b), 4 - 10 + 18);
  Vec3f c = cross(a, b);
  EXPECT_FLOAT_EQ(dot(c, a), 0.0f);
  EXPECT_FLOAT_EQ(dot(c, b), 0.0f);
  EXPECT_EQ(cross(Vec3f(1, 0, 0), Vec3f(0, 1, 0)), Vec3f(0, 0, 1));  // right-handed
  EXPECT_FLOAT_EQ(length(Vec3f(3, 4, 0)), 5.0f);
  EXPECT_NEAR(length(normalize(b)), 1.0f, 1e-6f);
  EXPECT_EQ(min(a, b), Vec3f(1, -5, 3));
  EXPECT_EQ(max(a, b), Vec3f(4, 2, 6));
  EXPECT_FLOAT_EQ(maxComponent(b), 6.0f);
}

TEST(Vector, ReflectAndFaceForward) {
  Vec3f n(0, 0, 1), wi = normalize(Vec3f(1, 0, 1));
  Vec3f r = reflect(wi, n);
  EXPECT_NEAR(r.x, -wi.x, 1e-6f);
  EXPECT_NEAR(r.z, wi.z, 1e-6f);
  EXPECT_EQ(faceForward(n, Vec3f(0, 0, -1)), Vec3f(0, 0, -1));
  EXPECT_EQ(faceForward(n, Vec3f(0, 1, 1)), n);
}

TEST(Frame, IsOrthonormalForManyNormals) {
  PCG32 rng(3, 5);
  std::vector<Vec3f> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, normalize(Vec3f(0, 1e-7f, -1))};
  for (int i = 0; i < 1000; ++i) normals.push_back(warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()}));
  for (const Vec3f& n : normals) {
    Frame f(n);
    EXPECT_NEAR(length(f.s), 1.0f, 1e-5f);
    EXPECT_NEAR(length(f.t), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.t, f.n), 0.0f, 1e-5f);
    // Right-handed: s x t = n.
    Vec3f st = cross(f.s, f.t);
    EXPECT_NEAR(distance(st, f.n), 0.0f, 1e-5f) << "normal " << n;
    Vec3f v(0.3f, -0.4f, 0.5f);
    EXPECT_NEAR(distance(f.toWorld(f.toLocal(v)), v), 0.0f, 1e-5f);
    EXPECT_NEAR(Frame::cosTheta(f.toLocal(n)), 1.0f, 1e-5f);
  }
}

TEST(PCG32, IsDeterministicPerSeedAndStream) {
  PCG32 a(42, 1), b(42, 1), c(42, 2), d(43, 1);
  bool differsByStream = false, differsBySeed = false;
  for (int i = 0; i < 100; ++i) {
    uint32_t va = a.nextUInt(), vc = c.nextUInt(), vd = d.nextUInt();
    EXPECT_EQ(va, b.nextUInt());
    differsByStream |= va != vc;
    differsBySeed |= va != vd;
  }
  EXPECT_TRUE(differsByStream);
  EXPECT_TRUE(differsBySeed);
}

TEST(PCG32, AdvanceJumpsForwardAndBack) {
  PCG32 rng(7, 3), ref(7, 3);
  std::vector<uint32_t> seq;
  for (int i = 0; i < 1000; ++i) seq.push_back(ref.nextUInt());
  rng.advance(500);
  EXPECT_EQ(rng.nextUInt(), seq[500]);
  rng.advance(-301);  // back to index 200
  EXPECT_EQ(rng.nextUInt(), seq[200]);
}

TEST(PCG32, FloatsAreInUnitIntervalWithTheRightMean) {
  PCG32 rng;
  double sum = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    float f = rng.nextFloat();
    ASSERT_GE(f, 0.0f);
    ASSERT_LT(f, 1.0f);
    double d = rng.nextDouble();
    ASSERT_GE(d, 0.0);
    ASSERT_LT(d, 1.0);
    sum += f;
  }
  // Standard error of the mean of U(0,1) is sqrt(1/12/n); allow 5 sigma.
  EXPECT_NEAR(sum / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
}

TEST(PCG32, BoundedIntegersCoverTheRange) {
  PCG32 rng(11, 13);
  std::set<uint32_t> seen;
  for (int i = 0; i < 1000; ++i) {
    uint32_t v = rng.nextUInt(7);
    ASSERT_LT(v, 7u);
    seen.insert(v);
  }
  EXPECT_EQ(seen.size(), 7u);
}

TEST(BoundingBox, StartsEmptyAndGrows) {
  BoundingBox3f b;
  EXPECT_FALSE(b.valid());
  EXPECT_EQ(b.boundingRadius(), 0.0f);
  b.expand(Point3f(1, 2, 3));
  EXPECT_TRUE(b.valid());
  EXPECT_EQ(b.extents(), Vec3f(0, 0, 0));
  b.expand(Point3f(-1, 0, 5));
  EXPECT_EQ(b.min, Point3f(-1, 0, 3));
  EXPECT_EQ(b.max, Point3f(1, 2, 5));
  EXPECT_EQ(b.center(), Point3f(0, 1, 4));
  EXPECT_TRUE(b.contains(Point3f(0, 1, 4)));
  EXPECT_FALSE(b.contains(Point3f(0, 3, 4)));
  EXPECT_NEAR(b.boundingRadius(), std::sqrt(3.0f), 1e-6f);
  BoundingBox3f other(Point3f(5, 5, 5), Point3f(4, 4, 4));  // corners in any order
  EXPECT_EQ(other.min, Point3f(4, 4, 4));
  b.expand(other);
  EXPECT_EQ(b.max, Point3f(5, 5, 5));
}
