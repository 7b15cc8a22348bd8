// Smooth BSDFs in the path tracer against closed forms: a camera looks along
// the normal through a glass slab at a uniform emitter behind it.
//
// At normal incidence each face reflects R = ((eta - 1) / (eta + 1))^2. The
// path tracer picks reflection or refraction at each face with probability
// R or 1 - R (weight 1; the radiance scaling 1/eta^2 on entering and eta^2
// on leaving cancel), and depth counts segments: camera -> front face (1)
// -> back face (2) -> emitter (3). Light that went straight through needs
// 3 segments, and each round trip inside the slab adds 2 and a factor R^2:
//   L(max_depth = k) = Le (1 - R)^2 sum_{j=0}^{floor((k - 3) / 2)} R^{2j},
// which is Le (1 - R)^2 for k = 3 or 4 and, unbounded, the full series
//   Le (1 - R)^2 / (1 - R^2) = Le (1 - R) / (1 + R).
// Each Li is Le or 0, so the estimator's standard error is known; tolerances
// are 5 standard errors (li_estimate.h).
#include <gtest/gtest.h>

#include <femto/math/warp.h>
#include <femto/scattering/fresnel.h>

#include "li_estimate.h"

using namespace femto;
using namespace femto::test;

namespace {

const Color3f Le(1.0f, 2.0f, 0.5f);

/// `shape` (with its BSDF) in front of an emitter z = -2 facing +z (black,
/// so light it reflects adds nothing).
std::shared_ptr<Scene> sceneInFrontOfEmitter(const std::string& shape, int maxDepth) {
  return loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="max_depth" value=")", maxDepth, R"("/></integrator>
  <sensor type="perspective"><film type="hdrfilm"/><sampler type="independent"/></sensor>
  )", shape, R"(
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/><translate z="-2"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf>
    <emitter type="area"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
  </shape>
</scene>)"));
}

/// Slab |z| <= 0.5 (the cube scaled to 20 x 20 x 1) of a dielectric.
std::string dielectricSlab(float eta) {
  return str(R"(<shape type="cube">
    <transform name="to_world"><scale x="10" y="10" z="0.5"/></transform>
    <bsdf type="dielectric"><float name="int_ior" value=")", eta, R"("/><float name="ext_ior" value="1"/></bsdf>
  </shape>)");
}

/// Camera rays along -z through the middle of the slab.
Ray downTheNormal(PCG32& rng) { return Ray(Point3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 3.0f), Vec3f(0, 0, -1)); }

/// The closed form above.
float slabTransmittance(float eta, int maxDepth) {
  const float r = fresnelDielectric(1.0f, eta);
  if (maxDepth < 0) return (1 - r) / (1 + r);
  float sum = 0.0f;
  for (int j = 0; 2 * j + 3 <= maxDepth; ++j) sum += std::pow(r, 2.0f * j);
  return (1 - r) * (1 - r) * sum;
}

}  // namespace

TEST(DielectricSlab, TransmittanceFollowsTheInternalReflectionSeries) {
  // eta = 1.5 (R = 0.04) as in the brief; eta = 2.4 (R = 0.17) makes the
  // series terms large enough that counting one pass more or less than the
  // tracer does would fail by several standard errors.
  for (float eta : {1.5f, 2.4f}) {
    for (int maxDepth : {2, 3, 4, 5, -1}) {
      SCOPED_TRACE(str("eta = ", eta, ", max_depth = ", maxDepth));
      auto scene = sceneInFrontOfEmitter(dielectricSlab(eta), maxDepth);
      Estimate e = estimateLi(*scene, 100000, downTheNormal);
      expectWithinErrorBars(e, Le * slabTransmittance(eta, maxDepth));
    }
  }
  // The two forms really differ at eta = 2.4 by more than the test resolves.
  EXPECT_GT(slabTransmittance(2.4f, -1) - slabTransmittance(2.4f, 3), 0.02f);
}

TEST(DielectricSlab, ThinDielectricPaneSumsTheSeriesInOneEvent) {
  // The same slab as an infinitely thin pane: T' = 1 - R' = (1 - R) / (1 + R),
  // reached with two segments (camera -> pane -> emitter).
  const std::string pane = R"(<shape type="rectangle">
    <transform name="to_world"><scale value="10"/></transform>
    <bsdf type="thindielectric"><float name="int_ior" value="2.4"/><float name="ext_ior" value="1"/></bsdf>
  </shape>)";
  Estimate e = estimateLi(*sceneInFrontOfEmitter(pane, 2), 100000, downTheNormal);
  expectWithinErrorBars(e, Le * slabTransmittance(2.4f, -1));
}

TEST(ConductorMirror, ReflectsTheEmitterWithTheFresnelTerm) {
  // A gold mirror z = 0 under an emitter z = 3 facing down: the camera sees
  // the emitter in the mirror, scaled by the conductor Fresnel reflectance.
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"/>
  <sensor type="perspective"><film type="hdrfilm"/><sampler type="independent"/></sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/></transform>
    <bsdf type="conductor"><string name="material" value="Au"/></bsdf>
  </shape>
  <shape type="rectangle">
    <boolean name="flip_normals" value="true"/>
    <transform name="to_world"><scale value="50"/><translate z="3"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0"/></bsdf>
    <emitter type="area"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
  </shape>
</scene>)"));
  auto gold = lookupConductor("Au");
  for (float cosTheta : {1.0f, 0.7f, 0.3f}) {
    SCOPED_TRACE(str("cos theta = ", cosTheta));
    const Vec3f d(std::sqrt(1 - cosTheta * cosTheta), 0.0f, -cosTheta);
    Estimate e = estimateLi(*scene, 16, [&](PCG32&) { return Ray(Point3f(0, 0, 1) - d * (1.0f / cosTheta), d); });
    expectWithinErrorBars(e, Le * fresnelConductor(cosTheta, gold->first, gold->second));
  }
}

TEST(LosslessSurfacesInAFurnace, SeeTheUniformEnvironmentUnchanged) {
  // A sphere inside an environment of uniform radiance Le. If its surface
  // loses no energy (glass in either transport mode, a thin pane, a null
  // surface, a mask blending glass with pass-through), every path eventually
  // escapes carrying Le: refraction's 1/eta^2 on the way in is undone on the
  // way out, and Russian roulette (which must ignore that scaling inside the
  // glass) stays unbiased. So L = Le exactly, in expectation.
  const char* surfaces[] = {
      R"(<bsdf type="dielectric"/>)",
      R"(<bsdf type="dielectric"><float name="int_ior" value="2.4"/></bsdf>)",
      R"(<bsdf type="thindielectric"/>)",
      R"(<bsdf type="null"/>)",
      R"(<bsdf type="mask"><float name="opacity" value="0.4"/><bsdf type="dielectric"/></bsdf>)",
  };
  for (const char* bsdf : surfaces) {
    SCOPED_TRACE(bsdf);
    auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"><integer name="rr_depth" value="2"/></integrator>
  <sensor type="perspective"><film type="hdrfilm"/><sampler type="independent"/></sensor>
  <shape type="sphere">)", bsdf, R"(</shape>
  <emitter type="constant"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
</scene>)"));
    // Rays from outside aimed at random points of the sphere's disk.
    Estimate e = estimateLi(*scene, 20000, [](PCG32& rng) {
      Point2f disk = warp::squareToUniformDiskConcentric({rng.nextFloat(), rng.nextFloat()});
      return Ray(Point3f(disk.x, disk.y, 4.0f), Vec3f(0, 0, -1));
    });
    expectWithinErrorBars(e, Le);
  }
}

TEST(PlasticUnderUniformSky, ReflectsItsAlbedoWithMisAcrossDeltaAndDiffuseLobes) {
  // A plastic plane under an environment of uniform radiance Le reflects
  // L(wi) = Le * albedo(wi), where (see plastic.cpp)
  //   albedo = R(wi) + (1 - R(wi)) * D * rho / ((1 - Fdr_int) eta^2),
  //   D = 2 * integral_0^1 (1 - R(mu)) mu dmu   (computed here by quadrature).
  // The path finds the specular part only by BSDF sampling (weight 1) and the
  // diffuse part by both emitter and BSDF sampling (MIS): any double counting
  // or missing weight across the two lobes shows up here.
  const float eta = 1.49f;
  const Color3f rho(0.2f, 0.5f, 0.8f);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"/>
  <sensor type="perspective"><film type="hdrfilm"/><sampler type="independent"/></sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale value="100"/></transform>
    <bsdf type="plastic"><rgb name="diffuse_reflectance" value=")", rgb(rho), R"("/></bsdf>
  </shape>
  <emitter type="constant"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
</scene>)"));
  double d = 0.0;
  const int steps = 20000;
  for (int i = 0; i < steps; ++i) {
    double mu = (i + 0.5) / steps;
    d += 2.0 * (1.0 - fresnelDielectric(float(mu), eta)) * mu / steps;
  }
  const float fdrInt = fresnelDiffuseReflectance(1.0f / eta);
  for (float cosTheta : {1.0f, 0.5f, 0.15f}) {
    SCOPED_TRACE(str("cos theta = ", cosTheta));
    const Vec3f dir(std::sqrt(1 - cosTheta * cosTheta), 0.0f, -cosTheta);
    const float r = fresnelDielectric(cosTheta, eta);
    Color3f expected;
    for (int c = 0; c < 3; ++c) expected[c] = Le[c] * (r + (1 - r) * float(d) * rho[c] / ((1 - fdrInt) * eta * eta));
    expectWithinErrorBars(estimateLi(*scene, 40000, [&](PCG32&) { return Ray(Point3f(0, 0, 0) - dir * 2.0f, dir); }),
                          expected);
  }
}
