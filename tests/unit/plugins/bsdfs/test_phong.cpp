// phong (Mitsuba 0.6's modified Phong): albedo kd + ks at normal incidence
// (the lobe's (n + 2) / (2 pi) normalisation) and at most that elsewhere,
// sampling matches eval/pdf (chi-square, including a narrow lobe near
// grazing), reciprocity, Mitsuba 0.6's energy rescaling of kd + ks > 1,
// one-sidedness, errors at their file:line, and the 0.6 names in --strict.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/xml/loader.h>

#include "bsdf_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int ChiSquareTests = 4;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

std::shared_ptr<BSDF> phong(const Color3f& kd, const Color3f& ks, float exponent, bool ensure = true) {
  return makeBSDF("phong", [&](Properties& p) {
    p.setColor("diffuse_reflectance", kd);
    p.setColor("specular_reflectance", ks);
    p.setFloat("exponent", exponent);
    p.setBool("ensure_energy_conservation", ensure);
  });
}

}  // namespace

TEST(PhongBSDF, DefaultsAreMitsuba06s) {
  auto bsdf = makeBSDF("phong");
  const std::string text = bsdf->toString();
  EXPECT_NE(text.find("diffuse_reflectance=ConstantTexture[value=[0.5, "), std::string::npos) << text;
  EXPECT_NE(text.find("specular_reflectance=ConstantTexture[value=[0.2, "), std::string::npos) << text;
  EXPECT_NE(text.find("exponent=ConstantTexture[value=[30, "), std::string::npos) << text;
  EXPECT_EQ(bsdf->flags(), uint32_t(BSDFFlags::DiffuseReflection | BSDFFlags::GlossyReflection));
}

TEST(PhongBSDF, AlbedoIsKdPlusKsAtNormalIncidenceAndAtMostThatElsewhere) {
  const Color3f kd(0.5f, 0.3f, 0.1f), ks(0.3f, 0.4f, 0.6f);
  for (float exponent : {1.0f, 30.0f, 400.0f}) {
    SCOPED_TRACE(::testing::Message() << "exponent " << exponent);
    auto bsdf = phong(kd, ks, exponent);
    // At normal incidence the lobe lies wholly above the horizon: its albedo is exactly ks.
    expectAlbedoNear(albedo(*bsdf, localInteraction({0, 0, 1}), 100000), kd + ks);
    for (const Vec3f& d : {Vec3f(0.5f, 0.2f, 0.7f), Vec3f(0.9f, -0.2f, 0.15f)}) {
      AlbedoEstimate e = albedo(*bsdf, localInteraction(d), 100000);
      for (int c = 0; c < 3; ++c) EXPECT_LE(e.mean[c], kd[c] + ks[c] + 5.0f * e.standardError[c] + 1e-5f);
      // The diffuse part alone is reflected whatever the incidence.
      for (int c = 0; c < 3; ++c) EXPECT_GE(e.mean[c], kd[c] - 5.0f * e.standardError[c]);
    }
  }
}

TEST(PhongBSDF, EvalIsTheModifiedPhongFormula) {
  const float n = 12.0f;
  auto bsdf = phong(Color3f(0.4f), Color3f(0.5f), n);
  const Vec3f wi = normalize(Vec3f(0.4f, 0.1f, 0.8f)), wo = normalize(Vec3f(-0.35f, -0.05f, 0.8f));
  const float cosAlpha = dot(Vec3f(-wi.x, -wi.y, wi.z), wo);
  const float expected = (0.4f * InvPi + 0.5f * (n + 2) / (2 * Pi) * std::pow(cosAlpha, n)) * wo.z;
  EXPECT_NEAR(bsdf->eval(localInteraction(wi), wo).r, expected, 1e-5f * expected);
}

TEST(PhongBSDF, SamplesMatchEvalAndPdf) {
  struct Case {
    Vec3f wi;
    float exponent;
  };
  for (const Case& c : {Case{{0, 0, 1}, 30.0f}, Case{{0.5f, 0.3f, 0.6f}, 5.0f}, Case{{0.9f, 0.1f, 0.12f}, 80.0f},
                        Case{{-0.3f, 0.6f, 0.5f}, 1.0f}}) {
    SCOPED_TRACE(::testing::Message() << "wi " << c.wi << ", exponent " << c.exponent);
    auto bsdf = phong(Color3f(0.3f), Color3f(0.6f), c.exponent);
    SurfaceInteraction si = localInteraction(c.wi);
    EXPECT_EQ(checkSampleEvalPdf(*bsdf, si, 5000), 0.0);
    double smoothMass = 0.0;
    ChiSquareResult r = chiSquareSmoothLobes(*bsdf, si, smoothMass);
    EXPECT_GT(r.pValue, Significance) << r.message;
    // Lobe directions below the horizon fail: the pdf integrates to at most 1.
    EXPECT_LE(smoothMass, 1.0 + 1e-2);
  }
}

TEST(PhongBSDF, IsReciprocalAndOneSided) {
  auto bsdf = phong(Color3f(0.2f), Color3f(0.7f), 15.0f);
  const std::vector<Vec3f> dirs = {{0, 0, 1}, {0.3f, -0.2f, 0.8f}, {0.9f, 0.1f, 0.2f}, {-0.5f, 0.5f, 0.3f}};
  for (const Vec3f& a : dirs)
    for (const Vec3f& b : dirs) {
      const Vec3f wi = normalize(a), wo = normalize(Vec3f(-b.x, -b.y, b.z));
      const float fio = bsdf->eval(localInteraction(wi), wo).r / wo.z;
      const float foi = bsdf->eval(localInteraction(wo), wi).r / wi.z;
      EXPECT_NEAR(fio, foi, 1e-5f * std::max(1.0f, fio)) << wi << " " << wo;
    }
  SurfaceInteraction below = localInteraction({0.2f, 0.1f, -0.9f});
  BSDFSample bs;
  EXPECT_EQ(bsdf->sample(below, 0.5f, {0.5f, 0.5f}, bs), Color3f(0.0f));
  EXPECT_EQ(bs.pdf, 0.0f);
  EXPECT_EQ(bsdf->eval(localInteraction({0, 0, 1}), Vec3f(0, 0.6f, -0.8f)), Color3f(0.0f));
}

TEST(PhongBSDF, ScalesKdAndKsThatSumAboveOneAsMitsuba06) {
  const Color3f kd(0.8f, 0.2f, 0.2f), ks(0.5f);  // max channel sum 1.3
  SurfaceInteraction si = localInteraction({0, 0, 1});
  const float scale = 0.99f / 1.3f;
  expectAlbedoNear(albedo(*phong(kd, ks, 20.0f), si, 100000), (kd + ks) * scale);
  // ensure_energy_conservation = false keeps the values (and the excess energy).
  expectAlbedoNear(albedo(*phong(kd, ks, 20.0f, false), si, 100000), kd + ks);
  // Within the bound nothing is scaled.
  expectAlbedoNear(albedo(*phong(Color3f(0.5f), Color3f(0.5f), 20.0f), si, 100000), Color3f(1.0f));
}

TEST(PhongBSDF, BadParametersAreReportedWithFileAndLine) {
  const SourceLocation where{"scene.xml", 12};
  auto expectError = [&](const std::function<void(Properties&)>& setup, const std::string& words) {
    std::string message = errorMessageOf([&] { makeBSDF("phong", setup); });
    EXPECT_NE(message.find("scene.xml:12"), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  };
  expectError([&](Properties& p) { p.setFloat("exponent", -2.0, where); }, "must not be negative");
  expectError([&](Properties& p) { p.setColor("diffuse_reflectance", Color3f(-0.1f), where); }, "must not be negative");
  expectError([&](Properties& p) { p.setColor("specular_reflectance", Color3f(0.1f, -1, 0), where); },
              "must not be negative");
}

TEST(PhongBSDF, LoadsMitsuba06NamesInStrictMode) {
  LoadOptions strict;
  strict.strict = true;
  const char* xml = R"(<bsdf type="phong" version="0.6.0">
  <srgb name="diffuseReflectance" value="#202020"/>
  <spectrum name="specularReflectance" value="0.4"/>
  <float name="exponent" value="100"/>
  <boolean name="ensureEnergyConservation" value="false"/>
</bsdf>)";
  ObjectRef loaded = loadObjectFromString(xml, std::filesystem::temp_directory_path(), strict, "phong06.xml");
  std::string text = loaded->toString();
  EXPECT_NE(text.find("specular_reflectance=ConstantTexture[value=[0.4, "), std::string::npos) << text;
  EXPECT_NE(text.find("exponent=ConstantTexture[value=[100, "), std::string::npos) << text;
}
