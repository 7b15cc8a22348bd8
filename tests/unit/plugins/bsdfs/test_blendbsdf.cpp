// blendbsdf: the weight belongs to the second BSDF, a blend of two diffuse
// BSDFs has the blended albedo (exactly, per sample), delta components keep
// their share, sampling matches eval/pdf (chi-square), reciprocity, a
// texture weight varies over the surface, composition with twosided and
// mask, errors at their file:line, and Mitsuba 0.6 / 3 scenes in --strict.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/render/texture.h>
#include <femto/xml/loader.h>

#include "bsdf_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int ChiSquareTests = 3;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

std::shared_ptr<BSDF> phong(float exponent = 20.0f) {
  return makeBSDF("phong", [&](Properties& p) {
    p.setColor("diffuse_reflectance", Color3f(0.3f, 0.2f, 0.1f));
    p.setColor("specular_reflectance", Color3f(0.5f));
    p.setFloat("exponent", exponent);
  });
}

std::shared_ptr<BSDF> blend(std::shared_ptr<BSDF> first, std::shared_ptr<BSDF> second, float weight) {
  return makeBSDF("blendbsdf", [&](Properties& p) {
    p.setFloat("weight", weight);
    p.setObject("_arg_0", first);
    p.setObject("_arg_1", second);
  });
}

const std::vector<Vec3f> Directions = {{0, 0, 1}, {0.3f, -0.2f, 0.8f}, {0.9f, 0.1f, 0.2f}, {-0.5f, 0.5f, 0.05f}};

}  // namespace

TEST(BlendBSDF, TwoDiffuseBSDFsHaveTheBlendedAlbedo) {
  const Color3f rho0(0.8f, 0.4f, 0.1f), rho1(0.1f, 0.5f, 0.9f);
  const float t = 0.3f;
  auto bsdf = blend(makeDiffuse(rho0), makeDiffuse(rho1), t);
  EXPECT_EQ(bsdf->flags(), uint32_t(BSDFFlags::DiffuseReflection));
  const Color3f expected = rho0 * (1 - t) + rho1 * t;
  for (const Vec3f& d : Directions) {
    SurfaceInteraction si = localInteraction(d);
    // Both terms sample the same cosine density, so every sample weighs exactly the blended albedo.
    AlbedoEstimate e = albedo(*bsdf, si, 4000);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(e.mean[c], expected[c], 1e-5f);
      EXPECT_LT(e.standardError[c], 1e-5f);
    }
    const Vec3f wo = normalize(Vec3f(0.2f, 0.4f, 0.7f));
    const Color3f f = bsdf->eval(si, wo);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], expected[c] * InvPi * wo.z, 1e-6f);
  }
}

TEST(BlendBSDF, WeightIsTheWeightOfTheSecondBSDF) {
  auto first = makeDiffuse(Color3f(0.5f)), second = phong();
  SurfaceInteraction si = localInteraction({0.3f, 0.1f, 0.9f});
  const Vec3f wo = normalize(Vec3f(-0.3f, -0.1f, 0.9f));  // near the mirror direction: phong's lobe
  ASSERT_GT(std::abs(first->eval(si, wo).r - second->eval(si, wo).r), 0.1f);
  for (float t : {0.0f, 0.25f, 1.0f}) {
    auto bsdf = blend(first, second, t);
    const Color3f expected = first->eval(si, wo) * (1 - t) + second->eval(si, wo) * t;
    EXPECT_NEAR(bsdf->eval(si, wo).r, expected.r, 1e-5f * expected.r) << "t " << t;
    EXPECT_NEAR(bsdf->pdf(si, wo), first->pdf(si, wo) * (1 - t) + second->pdf(si, wo) * t, 1e-5f) << "t " << t;
  }
  // Default weight 0.5.
  auto halfway = makeBSDF("blendbsdf", [&](Properties& p) {
    p.setObject("_arg_0", first);
    p.setObject("_arg_1", second);
  });
  EXPECT_NEAR(halfway->eval(si, wo).g, 0.5f * (first->eval(si, wo).g + second->eval(si, wo).g), 1e-5f);
}

TEST(BlendBSDF, DeltaComponentsKeepTheirShare) {
  // A perfect mirror (first) blended with a white diffuse reflector: albedo (1 - t) + t.
  auto mirror = makeBSDF("conductor", [](Properties& p) { p.setString("material", "none"); });
  const float t = 0.4f;
  auto bsdf = blend(mirror, makeDiffuse(Color3f(0.5f)), t);
  EXPECT_EQ(bsdf->flags(), uint32_t(BSDFFlags::DeltaReflection | BSDFFlags::DiffuseReflection));
  SurfaceInteraction si = localInteraction({0.4f, 0.2f, 0.7f});
  expectAlbedoNear(albedo(*bsdf, si, 40000), Color3f((1 - t) * 1.0f + t * 0.5f));
  const double deltaFraction = checkSampleEvalPdf(*bsdf, si, 20000);
  EXPECT_NEAR(deltaFraction, 1 - t, 5.0 * std::sqrt(t * (1 - t) / 20000));
  // eval and pdf see only the diffuse term, scaled by t.
  const Vec3f wo = normalize(Vec3f(0.1f, 0.3f, 0.8f));
  EXPECT_NEAR(bsdf->eval(si, wo).r, t * 0.5f * InvPi * wo.z, 1e-6f);
  EXPECT_NEAR(bsdf->pdf(si, wo), t * InvPi * wo.z, 1e-6f);
}

TEST(BlendBSDF, SamplesMatchEvalAndPdf) {
  // Glossy + diffuse blended with plastic (delta + diffuse): overlapping lobes.
  auto plastic = makeBSDF("plastic", [](Properties& p) { p.setColor("diffuse_reflectance", Color3f(0.6f)); });
  auto bsdf = blend(phong(), plastic, 0.35f);
  for (const Vec3f& d : {Vec3f(0, 0, 1), Vec3f(0.6f, 0.2f, 0.5f), Vec3f(0.9f, 0.1f, 0.15f)}) {
    SCOPED_TRACE(::testing::Message() << "wi " << d);
    SurfaceInteraction si = localInteraction(d);
    checkSampleEvalPdf(*bsdf, si, 5000);
    expectAlbedoAtMost(albedo(*bsdf, si, 40000), 1.0f);
    double smoothMass = 0.0;
    ChiSquareResult r = chiSquareSmoothLobes(*bsdf, si, smoothMass);
    EXPECT_GT(r.pValue, Significance) << r.message;
  }
}

TEST(BlendBSDF, IsReciprocal) {
  auto bsdf = blend(makeDiffuse(Color3f(0.7f)), phong(8.0f), 0.6f);
  for (const Vec3f& a : Directions)
    for (const Vec3f& b : Directions) {
      const Vec3f wi = normalize(a), wo = normalize(Vec3f(-b.x, b.y, b.z));
      const Color3f fio = bsdf->eval(localInteraction(wi), wo) / wo.z;
      const Color3f foi = bsdf->eval(localInteraction(wo), wi) / wi.z;
      EXPECT_NEAR(fio.g, foi.g, 1e-5f * std::max(1.0f, fio.g)) << wi << " " << wo;
    }
}

TEST(BlendBSDF, TextureWeightVariesOverTheSurface) {
  Properties checker("checkerboard");
  checker.setColor("color0", Color3f(0.0f));
  checker.setColor("color1", Color3f(1.0f));
  auto weight = createPlugin<Texture>(ObjectKind::Texture, checker);
  auto first = makeDiffuse(Color3f(0.2f)), second = makeDiffuse(Color3f(0.8f));
  auto bsdf = makeBSDF("blendbsdf", [&](Properties& p) {
    p.setObject("weight", weight);
    p.setObject("_arg_0", first);
    p.setObject("_arg_1", second);
  });
  SurfaceInteraction si = localInteraction({0, 0, 1});
  const Vec3f wo(0, 0, 1);
  si.uv = Point2f(0.25f, 0.25f);  // color0: weight 0, the first BSDF
  EXPECT_NEAR(bsdf->eval(si, wo).r, 0.2f * InvPi, 1e-6f);
  si.uv = Point2f(0.75f, 0.25f);  // color1: weight 1, the second BSDF
  EXPECT_NEAR(bsdf->eval(si, wo).r, 0.8f * InvPi, 1e-6f);
  BSDFSample bs;
  EXPECT_NEAR(bsdf->sample(si, 0.01f, {0.3f, 0.3f}, bs).r, 0.8f, 1e-5f);
}

TEST(BlendBSDF, ComposesWithTwoSidedAndMaskAndKeepsTheDelay) {
  auto inner = blend(makeDiffuse(Color3f(0.2f)), phong(), 0.5f);
  auto both = makeBSDF("twosided", [&](Properties& p) { p.setObject("_arg_0", inner); });
  const Vec3f wi(0.3f, 0.2f, 0.8f), wo(-0.2f, -0.3f, 0.7f);
  const Vec3f wiBack(wi.x, wi.y, -wi.z), woBack(wo.x, wo.y, -wo.z);
  EXPECT_NEAR(both->eval(localInteraction(wiBack), woBack).r, inner->eval(localInteraction(wi), wo).r, 1e-6f);
  checkSampleEvalPdf(*both, localInteraction(wiBack), 2000);
  // A blend may hold a transmitting BSDF, and be masked.
  auto translucent = blend(makeDiffuse(Color3f(0.5f)), makeBSDF("difftrans"), 0.5f);
  EXPECT_EQ(translucent->flags(), uint32_t(BSDFFlags::DiffuseReflection | BSDFFlags::DiffuseTransmission));
  auto masked = makeBSDF("mask", [&](Properties& p) {
    p.setFloat("opacity", 0.5f);
    p.setObject("bsdf", translucent);
  });
  SurfaceInteraction si = localInteraction(wi);
  // 0.5 passes through; the other half: 0.5 reflected (albedo 0.5) + 0.5 transmitted (0.5).
  expectAlbedoNear(albedo(*masked, si, 40000), Color3f(0.5f + 0.5f * 0.5f));
  checkSampleEvalPdf(*masked, si, 2000);
  auto delayed = makeBSDF("blendbsdf", [&](Properties& p) {
    p.setObject("_arg_0", makeDiffuse(Color3f(0.5f)));
    p.setObject("_arg_1", phong());
    p.setFloat("delay", 0.25);
  });
  EXPECT_TRUE(delayed->hasDelay());
  EXPECT_NEAR(delayed->sampleDelay(0.5f), 0.25, 1e-9);
}

TEST(BlendBSDF, BadParametersAreReportedWithFileAndLine) {
  const SourceLocation where{"scene.xml", 12};
  std::string message = errorMessageOf(
      [&] { makeBSDF("blendbsdf", [&](Properties& p) { p.setObject("_arg_0", makeDiffuse(Color3f(0.5f))); }); });
  EXPECT_NE(message.find("scene.xml:3"), std::string::npos) << message;
  EXPECT_NE(message.find("exactly two nested <bsdf>, got 1"), std::string::npos) << message;
  message = errorMessageOf([&] {
    makeBSDF("blendbsdf", [&](Properties& p) {
      p.setFloat("weight", 1.5f, where);
      p.setObject("_arg_0", makeDiffuse(Color3f(0.5f)));
      p.setObject("_arg_1", makeDiffuse(Color3f(0.5f)));
    });
  });
  EXPECT_NE(message.find("scene.xml:12"), std::string::npos) << message;
  EXPECT_NE(message.find("must lie in [0, 1]"), std::string::npos) << message;
}

TEST(BlendBSDF, LoadsMitsuba06And3ScenesInStrictMode) {
  LoadOptions strict;
  strict.strict = true;
  const char* legacy = R"(<bsdf type="blendbsdf" version="0.6.0">
  <float name="weight" value="0.25"/>
  <bsdf type="diffuse"><rgb name="reflectance" value="0.8 0.2 0.2"/></bsdf>
  <bsdf type="phong"><spectrum name="specularReflectance" value="0.4"/><float name="exponent" value="50"/></bsdf>
</bsdf>)";
  ObjectRef loaded = loadObjectFromString(legacy, std::filesystem::temp_directory_path(), strict, "blend06.xml");
  std::string text = loaded->toString();
  EXPECT_NE(text.find("BlendBSDF[weight="), std::string::npos) << text;
  EXPECT_LT(text.find("DiffuseBSDF"), text.find("PhongBSDF")) << "document order: " << text;
  const char* modern = R"(<bsdf type="blendbsdf" version="3.0.0">
  <texture type="checkerboard" name="weight"/>
  <bsdf type="conductor"/>
  <bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="0.1"/></bsdf>
</bsdf>)";
  EXPECT_NO_THROW(loadObjectFromString(modern, std::filesystem::temp_directory_path(), strict, "blend3.xml"));
}
