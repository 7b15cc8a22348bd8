// difftrans (Mitsuba 0.6's diffuse transmitter): everything that is not
// absorbed leaves from the far side (albedo = transmittance, nothing
// reflected), from either side; sampling matches eval/pdf (chi-square),
// reciprocity, errors at their file:line, and the 0.6 scene name in --strict.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/xml/loader.h>

#include "bsdf_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int ChiSquareTests = 2;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

}  // namespace

TEST(DiffuseTransmitterBSDF, TransmitsTheTransmittanceFromEitherSideAndReflectsNothing) {
  const Color3f t(0.7f, 0.5f, 0.2f);
  auto bsdf = makeBSDF("difftrans", [&](Properties& p) { p.setColor("transmittance", t); });
  EXPECT_EQ(bsdf->flags(), uint32_t(BSDFFlags::DiffuseTransmission));
  EXPECT_NE(makeBSDF("difftrans")->toString().find("ConstantTexture[value=[0.5, "), std::string::npos);  // default 0.5
  for (float side : {1.0f, -1.0f}) {
    SurfaceInteraction si = localInteraction({0.3f, 0.2f, 0.6f * side});
    AlbedoEstimate e = albedo(*bsdf, si, 2000);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.mean[c], t[c], 1e-5f);  // every sample weighs t
    checkSampleEvalPdf(*bsdf, si, 2000);
    PCG32 rng(4, 2);
    for (int i = 0; i < 200; ++i) {
      BSDFSample bs;
      bsdf->sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs);
      EXPECT_LT(bs.wo.z * si.wi.z, 0.0f);
      EXPECT_EQ(bs.sampledFlags, uint32_t(BSDFFlags::DiffuseTransmission));
    }
    const Vec3f sameSide(0.1f, 0.1f, 0.9f * side);
    EXPECT_EQ(bsdf->eval(si, normalize(sameSide)), Color3f(0.0f));
    EXPECT_EQ(bsdf->pdf(si, normalize(sameSide)), 0.0f);
    double smoothMass = 0.0;
    ChiSquareResult r = chiSquareSmoothLobes(*bsdf, si, smoothMass);
    EXPECT_GT(r.pValue, Significance) << r.message;
    EXPECT_NEAR(smoothMass, 1.0, 1e-2);
  }
}

TEST(DiffuseTransmitterBSDF, IsReciprocal) {
  auto bsdf = makeBSDF("difftrans");
  const Vec3f wi = normalize(Vec3f(0.3f, 0.4f, 0.5f)), wo = normalize(Vec3f(-0.6f, 0.1f, -0.3f));
  EXPECT_NEAR(bsdf->eval(localInteraction(wi), wo).r / std::abs(wo.z),
              bsdf->eval(localInteraction(wo), wi).r / std::abs(wi.z), 1e-6f);
  EXPECT_NEAR(bsdf->eval(localInteraction(wi), wo).r, 0.5f * InvPi * std::abs(wo.z), 1e-6f);
}

TEST(DiffuseTransmitterBSDF, BadParametersAreReportedWithFileAndLine) {
  std::string message = errorMessageOf([] {
    makeBSDF("difftrans", [](Properties& p) { p.setColor("transmittance", Color3f(-0.5f), {"scene.xml", 12}); });
  });
  EXPECT_NE(message.find("scene.xml:12"), std::string::npos) << message;
  EXPECT_NE(message.find("must not be negative"), std::string::npos) << message;
}

TEST(DiffuseTransmitterBSDF, LoadsAMitsuba06SceneInStrictMode) {
  LoadOptions strict;
  strict.strict = true;
  const char* xml = R"(<bsdf type="difftrans" version="0.6.0">
  <spectrum name="transmittance" value="0.3"/>
</bsdf>)";
  ObjectRef loaded = loadObjectFromString(xml, std::filesystem::temp_directory_path(), strict, "difftrans06.xml");
  EXPECT_NE(loaded->toString().find("transmittance=ConstantTexture[value=[0.3, "), std::string::npos)
      << loaded->toString();
}
