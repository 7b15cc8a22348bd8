// BSDF and emitter plugins: diffuse, area, point. Sampling routines are
// checked against their densities with the chi-square test of chi2.h.
#include <gtest/gtest.h>

#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>
#include <femto/render/shape.h>

#include "chi2.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

// Chi-square tests in this file, for the Sidak correction.
constexpr int ChiSquareTests = 2;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

std::shared_ptr<BSDF> makeDiffuse(const Color3f& reflectance) {
  Properties props("diffuse");
  props.setColor("reflectance", reflectance);
  return createPlugin<BSDF>(ObjectKind::BSDF, props);
}

SurfaceInteraction localInteraction(const Vec3f& wi) {
  SurfaceInteraction si;
  si.n = Normal3f(0, 0, 1);
  si.wi = normalize(wi);
  return si;
}

/// A sphere of radius 1 around `center` carrying an area emitter of radiance `Le`.
std::shared_ptr<Shape> makeEmittingSphere(const Point3f& center, const Color3f& Le) {
  Properties emitterProps("area");
  emitterProps.setColor("radiance", Le);
  Properties props("sphere");
  props.setPoint("center", center);
  props.setObject("emitter", createPlugin<Emitter>(ObjectKind::Emitter, emitterProps));
  return createPlugin<Shape>(ObjectKind::Shape, props);
}

}  // namespace

TEST(DiffuseBSDF, SamplingMatchesItsPdf) {
  auto bsdf = makeDiffuse(Color3f(0.5f));
  SurfaceInteraction si = localInteraction({0.3f, -0.2f, 0.8f});
  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) {
    BSDFSample bs;
    bsdf->sample(si, 0.5f, u, bs);
    return bs.wo;
  };
  std::function<double(const Vec3f&)> pdf = [&](const Vec3f& wo) { return bsdf->pdf(si, wo); };
  ChiSquareResult r = testSampler<Vec3f>(sphericalDomain(24, 48), sample, pdf);
  EXPECT_GT(r.pValue, Significance) << r.message;
}

TEST(DiffuseBSDF, SampleWeightIsEvalOverPdfAndEqualsTheReflectance) {
  Color3f rho(0.2f, 0.5f, 0.9f);
  auto bsdf = makeDiffuse(rho);
  SurfaceInteraction si = localInteraction({0.1f, 0.4f, 0.5f});
  PCG32 rng;
  for (int i = 0; i < 100; ++i) {
    BSDFSample bs;
    Color3f weight = bsdf->sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs);
    ASSERT_GT(bs.pdf, 0.0f);
    EXPECT_EQ(bs.sampledFlags, uint32_t(BSDFFlags::DiffuseReflection));
    Color3f f = bsdf->eval(si, bs.wo);
    float pdf = bsdf->pdf(si, bs.wo);
    EXPECT_NEAR(pdf, bs.pdf, 1e-5f * pdf);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(weight[c], rho[c], 1e-6f);
      EXPECT_NEAR(f[c] / pdf, rho[c], 1e-4f * rho[c]);
    }
  }
}

TEST(DiffuseBSDF, AlbedoIsTheReflectance) {
  // Integral of f cos over the hemisphere = reflectance (energy conservation).
  Color3f rho(0.3f, 0.6f, 1.0f);
  auto bsdf = makeDiffuse(rho);
  SurfaceInteraction si = localInteraction({0, 0.6f, 0.8f});
  GridDomain<Vec3f> domain = sphericalDomain(64, 64);
  for (int c = 0; c < 3; ++c) {
    std::function<double(const Vec3f&)> fcos = [&](const Vec3f& wo) { return bsdf->eval(si, wo)[c]; };
    std::vector<double> cells = integrateCells(domain, fcos, 4);
    EXPECT_NEAR(std::accumulate(cells.begin(), cells.end(), 0.0), rho[c], 1e-3);
  }
}

TEST(DiffuseBSDF, IsOneSided) {
  auto bsdf = makeDiffuse(Color3f(0.5f));
  SurfaceInteraction above = localInteraction({0, 0, 1}), below = localInteraction({0, 0, -1});
  EXPECT_TRUE(bsdf->eval(above, {0, 0.6f, -0.8f}).isBlack());
  EXPECT_TRUE(bsdf->eval(below, {0, 0.6f, 0.8f}).isBlack());
  EXPECT_EQ(bsdf->pdf(below, {0, 0.6f, 0.8f}), 0.0f);
  BSDFSample bs;
  EXPECT_TRUE(bsdf->sample(below, 0.5f, {0.3f, 0.3f}, bs).isBlack());
  EXPECT_EQ(bs.pdf, 0.0f);
  EXPECT_FALSE(bsdf->eval(above, {0, 0.6f, 0.8f}).isBlack());
}

TEST(AreaEmitter, DirectionSamplingMatchesItsPdf) {
  // A 2 x 1.2 rectangle in the plane z = 2 facing down, seen from below. (A
  // sphere is a worse test subject: its solid-angle density diverges at the
  // silhouette, where cell integrals become inaccurate.)
  Properties emitterProps("area");
  emitterProps.setColor("radiance", Color3f(1.0f));
  Properties props("rectangle");
  props.setTransform("to_world", Transform::translate({0, 0, 2}) * Transform::rotate({1, 0, 0}, 180) *
                                     Transform::scale({1.0f, 0.6f, 1.0f}));
  props.setObject("emitter", createPlugin<Emitter>(ObjectKind::Emitter, emitterProps));
  auto shape = createPlugin<Shape>(ObjectKind::Shape, props);
  const Emitter* emitter = shape->emitter();
  const Point3f ref(0.4f, -0.3f, 0.0f);

  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) {
    DirectionSample ds;
    emitter->sampleDirection(ref, u, ds);
    return ds.d;
  };
  // The emitter's density for direction v, at the point where v meets the rectangle.
  std::function<double(const Vec3f&)> pdf = [&](const Vec3f& v) -> double {
    if (v.z <= 0.0f) return 0.0;
    float t = (2.0f - ref.z) / v.z;
    Point3f p = ref + v * t;
    if (std::abs(p.x) > 1.0f || std::abs(p.y) > 0.6f) return 0.0;
    DirectionSample ds;
    ds.p = p;
    ds.n = Normal3f(0, 0, -1);
    ds.d = v;
    ds.dist = t;
    return emitter->pdfDirection(ref, ds);
  };
  GridDomain<Vec3f> domain = sphericalDomain(36, 72);
  ChiSquareResult r = testSampler<Vec3f>(domain, sample, pdf, 1000000, 32);
  EXPECT_GT(r.pValue, Significance) << r.message;
  std::vector<double> cells = integrateCells<Vec3f>(domain, pdf, 32);
  EXPECT_NEAR(std::accumulate(cells.begin(), cells.end(), 0.0), 1.0, 2e-3);
}

TEST(AreaEmitter, SampleValueIsRadianceOverPdfAndOnlyTheFrontEmits) {
  Color3f Le(1.0f, 2.0f, 3.0f);
  auto shape = makeEmittingSphere({0, 0, 3}, Le);
  const Emitter* emitter = shape->emitter();
  PCG32 rng;
  for (int i = 0; i < 200; ++i) {
    DirectionSample ds;
    Color3f value = emitter->sampleDirection({0, 0, 0}, {rng.nextFloat(), rng.nextFloat()}, ds);
    EXPECT_FALSE(ds.delta);
    if (ds.pdf == 0.0f) {
      EXPECT_TRUE(value.isBlack());
      continue;
    }
    EXPECT_NEAR(ds.pdf, emitter->pdfDirection({0, 0, 0}, ds), 1e-4f * ds.pdf);
    EXPECT_NEAR(value.b * ds.pdf, 3.0f, 1e-4f);
    EXPECT_NEAR(length(ds.d), 1.0f, 1e-5f);
    EXPECT_NEAR(distance(ds.p, Point3f(0, 0, 3)), 1.0f, 1e-5f);
  }
  SurfaceInteraction si;
  si.n = Normal3f(0, 0, -1);
  EXPECT_EQ(emitter->eval(si, {0, 0.6f, -0.8f}), Le);
  EXPECT_TRUE(emitter->eval(si, {0, 0.6f, 0.8f}).isBlack());
  // Power of a Lambertian emitter: Le * pi * area.
  EXPECT_NEAR(emitter->power().g, 2.0f * Pi * 4.0f * Pi, 1e-3f);
  Ray ray;
  Color3f w = emitter->sampleRay({0.2f, 0.7f}, {0.4f, 0.1f}, ray);
  EXPECT_NEAR(w.g, emitter->power().g, 1e-3f);
  // Leaves the surface outward.
  EXPECT_GT(dot(ray.d, normalize(ray.o - Point3f(0, 0, 3))), 0.0f);
}

TEST(AreaEmitter, RequiresRadiance) {
  Properties props("area");
  props.setLocation({"scene.xml", 12});
  std::string message = errorMessageOf([&] { createPlugin<Emitter>(ObjectKind::Emitter, props); });
  EXPECT_NE(message.find("radiance"), std::string::npos) << message;
  EXPECT_NE(message.find("scene.xml:12"), std::string::npos) << message;
}

TEST(PointLight, InverseSquareLawAndPower) {
  Properties props("point");
  props.setColor("intensity", Color3f(2.0f, 4.0f, 8.0f));
  props.setPoint("position", {1, 2, 3});
  auto emitter = createPlugin<Emitter>(ObjectKind::Emitter, props);
  EXPECT_TRUE(emitter->isDelta());
  DirectionSample ds;
  Color3f value = emitter->sampleDirection({1, 2, 1}, {0.5f, 0.5f}, ds);
  EXPECT_TRUE(ds.delta);
  EXPECT_EQ(ds.pdf, 1.0f);
  EXPECT_FLOAT_EQ(ds.dist, 2.0f);
  EXPECT_EQ(ds.d, Vec3f(0, 0, 1));
  EXPECT_FLOAT_EQ(value.g, 4.0f / 4.0f);
  EXPECT_NEAR(emitter->power().r, 8.0f * Pi, 1e-5f);
  Ray ray;
  emitter->sampleRay({0.1f, 0.2f}, {0.3f, 0.4f}, ray);
  EXPECT_EQ(ray.o, Point3f(1, 2, 3));
}

TEST(PointLight, ToWorldPlacesTheLight) {
  Properties props("point");
  props.setTransform("to_world", Transform::translate({0, 5, 0}));
  auto emitter = createPlugin<Emitter>(ObjectKind::Emitter, props);
  DirectionSample ds;
  Color3f value = emitter->sampleDirection({0, 0, 0}, {0.5f, 0.5f}, ds);
  EXPECT_FLOAT_EQ(ds.dist, 5.0f);
  EXPECT_FLOAT_EQ(value.r, 1.0f / 25.0f);  // default intensity 1
}
