// mixturebsdf (Mitsuba 0.6): the albedo is the weighted sum of the nested
// albedos; weights below 1 in total absorb the rest, weights above 1 are
// divided by their sum (unless ensure_energy_conservation is false);
// sampling picks by the normalised weights and matches eval/pdf
// (chi-square), delta terms keep their share, reciprocity, errors at their
// file:line, and Mitsuba 0.6's list syntax in --strict mode.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/xml/loader.h>

#include "bsdf_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int ChiSquareTests = 2;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

std::shared_ptr<BSDF> mixture(const std::string& weights, const std::vector<std::shared_ptr<BSDF>>& bsdfs,
                              const std::function<void(Properties&)>& extra = {}) {
  return makeBSDF("mixturebsdf", [&](Properties& p) {
    p.setString("weights", weights, {"scene.xml", 12});
    for (size_t i = 0; i < bsdfs.size(); ++i) p.setObject(str("_arg_", i), bsdfs[i]);
    if (extra) extra(p);
  });
}

}  // namespace

TEST(MixtureBSDF, AlbedoIsTheWeightedSumAndWeightsBelowOneAbsorb) {
  const Color3f rho0(0.9f, 0.1f, 0.4f), rho1(0.2f, 0.8f, 0.4f), rho2(0.5f);
  auto bsdf = mixture("0.2, 0.3;0.1", {makeDiffuse(rho0), makeDiffuse(rho1), makeDiffuse(rho2)});
  const Color3f expected = rho0 * 0.2f + rho1 * 0.3f + rho2 * 0.1f;
  for (const Vec3f& d : {Vec3f(0, 0, 1), Vec3f(0.6f, 0.3f, 0.4f)}) {
    AlbedoEstimate e = albedo(*bsdf, localInteraction(d), 4000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], expected[c], 1e-5f);  // same density: exact per sample
  }
  const Vec3f wo = normalize(Vec3f(0.1f, 0.2f, 0.9f));
  SurfaceInteraction si = localInteraction({0, 0, 1});
  EXPECT_NEAR(bsdf->eval(si, wo).g, expected.g * InvPi * wo.z, 1e-6f);
  EXPECT_NEAR(bsdf->pdf(si, wo), InvPi * wo.z, 1e-6f);  // sampled by the normalised weights
}

TEST(MixtureBSDF, WeightsAboveOneAreDividedByTheirSumUnlessTurnedOff) {
  const Color3f rho0(0.6f), rho1(0.8f);
  SurfaceInteraction si = localInteraction({0.2f, 0.1f, 0.9f});
  auto scaled = mixture("1 1", {makeDiffuse(rho0), makeDiffuse(rho1)});
  EXPECT_NE(scaled->toString().find("weights={0.5, 0.5}"), std::string::npos) << scaled->toString();
  expectAlbedoNear(albedo(*scaled, si, 4000), (rho0 + rho1) * 0.5f);
  auto kept = mixture("1 1", {makeDiffuse(rho0), makeDiffuse(rho1)},
                      [](Properties& p) { p.setBool("ensure_energy_conservation", false); });
  expectAlbedoNear(albedo(*kept, si, 4000), rho0 + rho1);  // as asked: not energy conserving
  // A sum of exactly 1 is left alone.
  EXPECT_NE(mixture("0.25,0.75", {makeDiffuse(rho0), makeDiffuse(rho1)})->toString().find("weights={0.25, 0.75}"),
            std::string::npos);
}

TEST(MixtureBSDF, SamplesMatchEvalAndPdfAndDeltaTermsKeepTheirShare) {
  auto mirror = makeBSDF("conductor", [](Properties& p) { p.setString("material", "none"); });
  auto phong = makeBSDF("phong", [](Properties& p) {
    p.setColor("specular_reflectance", Color3f(0.6f));
    p.setColor("diffuse_reflectance", Color3f(0.2f));
    p.setFloat("exponent", 10.0f);
  });
  auto bsdf = mixture("0.45, 0.15, 0.3", {mirror, makeDiffuse(Color3f(0.5f)), phong});
  EXPECT_EQ(bsdf->flags(),
            uint32_t(BSDFFlags::DeltaReflection | BSDFFlags::DiffuseReflection | BSDFFlags::GlossyReflection));
  SurfaceInteraction normal = localInteraction({0, 0, 1});
  // At normal incidence phong reflects kd + ks = 0.8: 0.45 * 1 + 0.15 * 0.5 + 0.3 * 0.8.
  expectAlbedoNear(albedo(*bsdf, normal, 100000), Color3f(0.45f + 0.075f + 0.24f));
  for (const Vec3f& d : {Vec3f(0, 0, 1), Vec3f(0.7f, 0.2f, 0.3f)}) {
    SCOPED_TRACE(::testing::Message() << "wi " << d);
    SurfaceInteraction si = localInteraction(d);
    const int n = 20000;
    const double delta = checkSampleEvalPdf(*bsdf, si, n);
    EXPECT_NEAR(delta, 0.45 / 0.9, 5.0 * std::sqrt(0.25 / n));  // chosen by normalised weight
    double smoothMass = 0.0;
    ChiSquareResult r = chiSquareSmoothLobes(*bsdf, si, smoothMass);
    EXPECT_GT(r.pValue, Significance) << r.message;
    EXPECT_LE(smoothMass, 0.45 / 0.9 + 1e-2);
  }
}

TEST(MixtureBSDF, IsReciprocal) {
  auto phong = makeBSDF("phong");
  auto bsdf = mixture("0.5, 0.5", {makeDiffuse(Color3f(0.3f)), phong});
  const Vec3f wi = normalize(Vec3f(0.3f, 0.2f, 0.7f)), wo = normalize(Vec3f(-0.25f, -0.2f, 0.8f));
  EXPECT_NEAR(bsdf->eval(localInteraction(wi), wo).r / wo.z, bsdf->eval(localInteraction(wo), wi).r / wi.z, 1e-5f);
}

TEST(MixtureBSDF, BadParametersAreReportedWithFileAndLine) {
  auto d = makeDiffuse(Color3f(0.5f));
  auto expectError = [](const std::function<void()>& build, const std::string& where, const std::string& words) {
    std::string message = errorMessageOf(build);
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  };
  expectError([&] { mixture("0.5, 0.5", {d}); }, "scene.xml:12", "gives 2 weights for 1 nested <bsdf>");
  expectError([&] { mixture("0.5, x", {d, d}); }, "scene.xml:12", "could not read \"x\" as a number");
  expectError([&] { mixture("0.5, -0.1", {d, d}); }, "scene.xml:12", "must not be negative");
  expectError([&] { mixture("0, 0", {d, d}); }, "scene.xml:12", "must sum to more than zero");
  expectError([&] { mixture(" , ", {d}); }, "scene.xml:12", "no weights given");
  expectError([&] { makeBSDF("mixturebsdf", [&](Properties& p) { p.setObject("_arg_0", d); }); }, "scene.xml:3",
              "needs a <string name=\"weights\">");
}

TEST(MixtureBSDF, LoadsMitsuba06SceneInStrictMode) {
  LoadOptions strict;
  strict.strict = true;
  const char* xml = R"(<bsdf type="mixturebsdf" version="0.6.0">
  <string name="weights" value="0.7, 0.2"/>
  <boolean name="ensureEnergyConservation" value="true"/>
  <bsdf type="conductor"><string name="material" value="Cr"/></bsdf>
  <bsdf type="diffuse"><rgb name="reflectance" value=".7 1 .7"/></bsdf>
</bsdf>)";
  ObjectRef loaded = loadObjectFromString(xml, std::filesystem::temp_directory_path(), strict, "mixture06.xml");
  EXPECT_NE(loaded->toString().find("weights={0.7, 0.2}"), std::string::npos) << loaded->toString();
}
