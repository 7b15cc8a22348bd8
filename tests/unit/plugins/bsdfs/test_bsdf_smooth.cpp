// Smooth BSDF plugins: dielectric, thindielectric, conductor, plastic,
// twosided, null, mask. Energy (white-furnace albedo), closed-form albedos,
// sample/eval/pdf consistency, chi-square tests of the smooth lobes,
// reciprocity, transport-mode scaling and errors for bad parameters.
#include <gtest/gtest.h>

#include <femto/scattering/fresnel.h>
#include <femto/scattering/ior.h>

#include "bsdf_test_util.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

// Chi-square tests in this file, for the Sidak correction.
constexpr int ChiSquareTests = 4;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

const SourceLocation Where{"scene.xml", 12};

std::shared_ptr<BSDF> make(const std::string& name, const std::function<void(Properties&)>& setup = {}) {
  return makeBSDF(name, setup);
}

std::shared_ptr<BSDF> makePlastic(const Color3f& rho, bool nonlinear = false, float ior = 1.49f) {
  return make("plastic", [&](Properties& p) {
    p.setColor("diffuse_reflectance", rho);
    p.setBool("nonlinear", nonlinear);
    p.setFloat("int_ior", ior);
  });
}

const std::vector<Vec3f> Directions = {{0, 0, 1}, {0.3f, -0.2f, 0.8f}, {0.9f, 0.1f, 0.2f}, {-0.5f, 0.5f, 0.05f}};

}  // namespace

// ---- dielectric --------------------------------------------------------

TEST(DielectricBSDF, DefaultsAreBk7InAir) {
  auto bsdf = make("dielectric");
  EXPECT_NE(bsdf->toString().find(str("int_ior=", *lookupIOR("bk7"))), std::string::npos) << bsdf->toString();
  EXPECT_EQ(bsdf->flags(), uint32_t(BSDFFlags::DeltaReflection | BSDFFlags::DeltaTransmission));
  EXPECT_TRUE(bsdf->isDeltaOnly());
}

TEST(DielectricBSDF, ChoosesReflectionByFresnelAndRefractsBySnell) {
  const float eta = 1.5f;
  auto bsdf = make("dielectric", [&](Properties& p) { p.setFloat("int_ior", eta); p.setFloat("ext_ior", 1.0); });
  for (float side : {1.0f, -1.0f}) {
    SurfaceInteraction si = localInteraction({0.4f, 0.2f, 0.6f * side});
    const float r = fresnelDielectric(si.wi.z, eta);
    const int n = 20000;
    int reflected = 0;
    PCG32 rng(1, 2);
    for (int i = 0; i < n; ++i) {
      BSDFSample bs;
      Color3f w = bsdf->sample(si, rng.nextFloat(), {0.5f, 0.5f}, bs, TransportMode::Importance);
      ASSERT_GT(bs.pdf, 0.0f);
      EXPECT_EQ(w, Color3f(1.0f));  // Importance: no radiance scaling, lossless
      if (bs.sampledFlags == BSDFFlags::DeltaReflection) {
        ++reflected;
        EXPECT_NEAR(bs.wo.x, -si.wi.x, 1e-6f);
        EXPECT_NEAR(bs.wo.z, si.wi.z, 1e-6f);
        EXPECT_FLOAT_EQ(bs.pdf, r);
      } else {
        ASSERT_EQ(bs.sampledFlags, uint32_t(BSDFFlags::DeltaTransmission));
        const float etaIT = side > 0 ? eta : 1.0f / eta;
        EXPECT_FLOAT_EQ(bs.eta, etaIT);
        EXPECT_LT(bs.wo.z * si.wi.z, 0.0f);
        EXPECT_NEAR(Frame::sinTheta(si.wi), etaIT * Frame::sinTheta(bs.wo), 1e-5f);
        EXPECT_FLOAT_EQ(bs.pdf, 1.0f - r);
      }
    }
    // Binomial: 5 standard deviations.
    EXPECT_NEAR(double(reflected) / n, r, 5.0 * std::sqrt(r * (1 - r) / n)) << "side " << side;
  }
}

TEST(DielectricBSDF, LosslessInImportanceTransportAndRadianceScalesByOneOverEtaSquared) {
  const float eta = 1.5f;
  auto bsdf = make("dielectric", [&](Properties& p) { p.setFloat("int_ior", eta); p.setString("ext_ior", "vacuum"); });
  for (const Vec3f& d : Directions) {
    for (float side : {1.0f, -1.0f}) {
      SurfaceInteraction si = localInteraction({d.x, d.y, d.z * side});
      // White furnace in Importance transport: every sample has weight 1.
      AlbedoEstimate importance = albedo(*bsdf, si, 2000, TransportMode::Importance);
      EXPECT_NEAR(importance.mean.r, 1.0f, 1e-5f);
      EXPECT_EQ(importance.standardError.r, 0.0f);
      // Radiance: the transmitted weight is the importance weight / eta_it^2 (eta^2 relation).
      for (float u1 : {0.999f, 0.5f}) {
        BSDFSample bsR, bsI;
        Color3f wR = bsdf->sample(si, u1, {0.3f, 0.3f}, bsR, TransportMode::Radiance);
        Color3f wI = bsdf->sample(si, u1, {0.3f, 0.3f}, bsI, TransportMode::Importance);
        ASSERT_EQ(bsR.sampledFlags, bsI.sampledFlags);
        const float scale = bsR.sampledFlags == BSDFFlags::DeltaTransmission ? 1.0f / (bsR.eta * bsR.eta) : 1.0f;
        EXPECT_NEAR(wR.g, wI.g * scale, 1e-6f);
      }
    }
  }
}

TEST(DielectricBSDF, RefractionIsReversible) {
  // The refracted direction, refracted again from the other side, returns
  // the original direction, with the inverse eta (so eta_in * eta_out = 1).
  auto bsdf = make("dielectric", [](Properties& p) { p.setString("int_ior", "water"); });
  SurfaceInteraction si = localInteraction({0.6f, -0.3f, 0.5f});
  BSDFSample there, back;
  bsdf->sample(si, 0.9999f, {0, 0}, there);
  ASSERT_EQ(there.sampledFlags, uint32_t(BSDFFlags::DeltaTransmission));
  bsdf->sample(localInteraction(there.wo), 0.9999f, {0, 0}, back);
  ASSERT_EQ(back.sampledFlags, uint32_t(BSDFFlags::DeltaTransmission));
  EXPECT_NEAR(back.wo.x, si.wi.x, 1e-5f);
  EXPECT_NEAR(back.wo.y, si.wi.y, 1e-5f);
  EXPECT_NEAR(back.wo.z, si.wi.z, 1e-5f);
  EXPECT_NEAR(there.eta * back.eta, 1.0f, 1e-6f);
}

TEST(DielectricBSDF, TotalInternalReflectionAlwaysReflects) {
  auto bsdf = make("dielectric", [](Properties& p) { p.setFloat("int_ior", 1.5); p.setFloat("ext_ior", 1.0); });
  SurfaceInteraction si = localInteraction({0.9f, 0.0f, -0.2f});  // inside, beyond the critical angle
  for (float u1 : {0.0f, 0.5f, 0.99999f}) {
    BSDFSample bs;
    Color3f w = bsdf->sample(si, u1, {0, 0}, bs);
    EXPECT_EQ(bs.sampledFlags, uint32_t(BSDFFlags::DeltaReflection));
    EXPECT_EQ(w, Color3f(1.0f));
    EXPECT_LT(bs.wo.z, 0.0f);
  }
}

// ---- thindielectric ----------------------------------------------------

TEST(ThinDielectricBSDF, ReflectanceSumsInternalReflectionsAndIsLossless) {
  const float eta = 1.5f;
  auto bsdf = make("thindielectric", [&](Properties& p) { p.setFloat("int_ior", eta); p.setFloat("ext_ior", 1.0); });
  for (const Vec3f& d : Directions) {
    for (float side : {1.0f, -1.0f}) {
      SurfaceInteraction si = localInteraction({d.x, d.y, d.z * side});
      const float r = fresnelDielectric(std::abs(si.wi.z), eta), t = 1 - r;
      const float rPane = r + t * t * r / (1 - r * r);
      const int n = 20000;
      PCG32 rng(4, 5);
      int reflected = 0;
      for (int i = 0; i < n; ++i) {
        BSDFSample bs;
        Color3f w = bsdf->sample(si, rng.nextFloat(), {0, 0}, bs);
        EXPECT_EQ(w, Color3f(1.0f));  // lossless in both transport modes
        EXPECT_EQ(bs.eta, 1.0f);
        if (bs.sampledFlags == BSDFFlags::DeltaReflection) {
          ++reflected;
          EXPECT_NEAR(bs.wo.z, si.wi.z, 1e-6f);
        } else {
          EXPECT_EQ(bs.wo, -si.wi);  // straight through
        }
      }
      EXPECT_NEAR(double(reflected) / n, rPane, 5.0 * std::sqrt(rPane * (1 - rPane) / n) + 1e-6);
    }
  }
  // At normal incidence R' = 2R / (1 + R).
  const float r0 = fresnelDielectric(1.0f, eta);
  BSDFSample bs;
  bsdf->sample(localInteraction({0, 0, 1}), 0.0f, {0, 0}, bs);
  EXPECT_NEAR(bs.pdf, 2 * r0 / (1 + r0), 1e-6f);
}

// ---- conductor ---------------------------------------------------------

TEST(ConductorBSDF, ReflectsWithTheConductorFresnelTerm) {
  auto gold = make("conductor", [](Properties& p) { p.setString("material", "Au"); });
  auto nk = lookupConductor("Au");
  ASSERT_TRUE(nk);
  for (const Vec3f& d : Directions) {
    SurfaceInteraction si = localInteraction(d);
    BSDFSample bs;
    Color3f w = gold->sample(si, 0.3f, {0.1f, 0.2f}, bs);
    Color3f expected = fresnelConductor(si.wi.z, nk->first, nk->second);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], expected[c], 1e-6f);
    EXPECT_NEAR(bs.wo.z, si.wi.z, 1e-6f);
    EXPECT_NEAR(bs.wo.x, -si.wi.x, 1e-6f);
    expectAlbedoAtMost(albedo(*gold, si, 100), 1.0f);
    // One-sided: nothing from below.
    BSDFSample below;
    EXPECT_TRUE(gold->sample(localInteraction({d.x, d.y, -d.z}), 0.3f, {0, 0}, below).isBlack());
  }
  // The default, "none", is a perfect mirror; explicit eta/k work too.
  BSDFSample bs;
  EXPECT_NEAR(make("conductor")->sample(localInteraction({0.5f, 0, 0.5f}), 0, {0, 0}, bs).g, 1.0f, 1e-6f);
  auto custom = make("conductor", [](Properties& p) { p.setColor("eta", Color3f(0.2f, 0.9f, 1.1f)); p.setColor("k", Color3f(3.9f, 2.4f, 2.1f)); });
  Color3f w = custom->sample(localInteraction({0, 0, 1}), 0, {0, 0}, bs);
  EXPECT_NEAR(w.r, ((0.8f * 0.8f) + 3.9f * 3.9f) / (1.2f * 1.2f + 3.9f * 3.9f), 1e-5f);
}

// ---- plastic -----------------------------------------------------------

TEST(PlasticBSDF, AlbedoMatchesTheLayerModel) {
  // albedo(wi) = R(wi) + (1 - R(wi)) (1 - Fdr_ext) x / eta^2, where the diffuse
  // light leaving is (1 - Fdr_ext) of what the base sends up, and
  // x = rho / (1 - Fdr_int) (linear) or rho / (1 - Fdr_int rho) (nonlinear).
  // Fdr values come from a fit good to ~0.5%: allow 1% of the diffuse part.
  const float eta = 1.49f;
  const float fdrInt = fresnelDiffuseReflectance(1 / eta), fdrExt = fresnelDiffuseReflectance(eta);
  const Color3f rho(0.2f, 0.6f, 1.0f);
  for (bool nonlinear : {false, true}) {
    auto bsdf = makePlastic(rho, nonlinear, eta);
    for (const Vec3f& d : Directions) {
      SurfaceInteraction si = localInteraction(d);
      const float r = fresnelDielectric(si.wi.z, eta);
      Color3f expected;
      for (int c = 0; c < 3; ++c) {
        float x = rho[c] / (1 - fdrInt * (nonlinear ? rho[c] : 1.0f));
        expected[c] = r + (1 - r) * (1 - fdrExt) * x / (eta * eta);
      }
      AlbedoEstimate e = albedo(*bsdf, si, 40000);
      expectAlbedoNear(e, expected, 0.01f);
      expectAlbedoAtMost(e, 1.0f + 0.01f);  // white base: lossless up to the fit's error
    }
  }
}

TEST(PlasticBSDF, SampleEvalPdfAgreeAndDiffuseLobePassesChiSquare) {
  auto bsdf = makePlastic(Color3f(0.3f, 0.5f, 0.7f));
  for (const Vec3f& d : {Vec3f(0.3f, -0.2f, 0.8f), Vec3f(0.9f, 0.1f, 0.15f)}) {
    SurfaceInteraction si = localInteraction(d);
    const double deltaFraction = checkSampleEvalPdf(*bsdf, si, 2000);
    (void)deltaFraction;
    double smoothMass = 0;
    ChiSquareResult r = chiSquareSmoothLobes(*bsdf, si, smoothMass);
    EXPECT_GT(r.pValue, Significance) << r.message;
    // The probability of the specular choice is 1 - (integral of pdf).
    const int n = 40000;
    PCG32 rng(21, 3);
    int specular = 0;
    for (int i = 0; i < n; ++i) {
      BSDFSample bs;
      bsdf->sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs);
      specular += (bs.sampledFlags & BSDFFlags::DeltaReflection) ? 1 : 0;
    }
    const double p = 1.0 - smoothMass;
    EXPECT_NEAR(double(specular) / n, p, 5.0 * std::sqrt(p * (1 - p) / n) + 2e-3);
  }
}

TEST(PlasticBSDF, IsReciprocalAndOneSided) {
  auto bsdf = makePlastic(Color3f(0.3f, 0.5f, 0.7f), true);
  for (const Vec3f& a : Directions)
    for (const Vec3f& b : Directions) {
      Vec3f wi = normalize(a), wo = normalize(b);
      Color3f fab = bsdf->eval(localInteraction(wi), wo) / wo.z;
      Color3f fba = bsdf->eval(localInteraction(wo), wi) / wi.z;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-5f * fab[c]);
    }
  SurfaceInteraction below = localInteraction({0.1f, 0.2f, -0.7f});
  EXPECT_TRUE(bsdf->eval(below, Vec3f(0, 0, 1)).isBlack());
  EXPECT_EQ(bsdf->pdf(below, Vec3f(0, 0, 1)), 0.0f);
  BSDFSample bs;
  EXPECT_TRUE(bsdf->sample(below, 0.5f, {0.5f, 0.5f}, bs).isBlack());
}

// ---- twosided ----------------------------------------------------------

TEST(TwoSidedBSDF, BackSideMirrorsTheFrontOrUsesTheSecondBSDF) {
  auto plastic = makePlastic(Color3f(0.3f, 0.5f, 0.7f));
  auto one = make("twosided", [&](Properties& p) { p.setObject("_arg_0", plastic); });
  auto two = make("twosided", [&](Properties& p) {
    p.setObject("_arg_0", plastic);
    p.setObject("_arg_1", makeDiffuse(Color3f(0.9f, 0.1f, 0.2f)));
  });
  EXPECT_EQ(one->flags(), plastic->flags());
  const Vec3f wiFront = normalize(Vec3f(0.3f, -0.2f, 0.8f)), woFront = normalize(Vec3f(-0.4f, 0.1f, 0.6f));
  SurfaceInteraction front = localInteraction(wiFront);
  SurfaceInteraction back = localInteraction({wiFront.x, wiFront.y, -wiFront.z});
  Vec3f woBack(woFront.x, woFront.y, -woFront.z);
  EXPECT_EQ(one->eval(back, woBack), plastic->eval(front, woFront));
  EXPECT_EQ(one->pdf(back, woBack), plastic->pdf(front, woFront));
  EXPECT_TRUE(one->eval(back, woFront).isBlack());  // no transmission
  BSDFSample bs;
  one->sample(back, 0.9f, {0.2f, 0.7f}, bs);
  EXPECT_LT(bs.wo.z, 0.0f);
  EXPECT_NEAR(bs.pdf, one->pdf(back, bs.wo), 1e-5f * bs.pdf);
  // Two BSDFs: the back side is the diffuse one.
  Color3f f = two->eval(back, woBack);
  EXPECT_NEAR(f.r, 0.9f * InvPi * woFront.z, 1e-6f);
  EXPECT_EQ(two->eval(front, woFront), plastic->eval(front, woFront));
  // Back-side samples pass the same checks and the chi-square test.
  checkSampleEvalPdf(*one, back, 2000);
  double smoothMass = 0;
  ChiSquareResult r = chiSquareSmoothLobes(*one, back, smoothMass);
  EXPECT_GT(r.pValue, Significance) << r.message;
  expectAlbedoAtMost(albedo(*two, back, 20000), 1.0f);
}

TEST(TwoSidedBSDF, WrapsAMaskAndKeepsPassThroughStraight) {
  auto mask = make("mask", [&](Properties& p) { p.setObject("bsdf", makeDiffuse(Color3f(0.5f))); });
  auto bsdf = make("twosided", [&](Properties& p) { p.setObject("_arg_0", mask); });
  for (float z : {0.6f, -0.6f}) {
    SurfaceInteraction si = localInteraction({0.3f, -0.4f, z});
    BSDFSample bs;
    EXPECT_EQ(bsdf->sample(si, 0.99f, {0.5f, 0.5f}, bs), Color3f(1.0f));  // u1 >= opacity: pass through
    EXPECT_EQ(bs.sampledFlags, uint32_t(BSDFFlags::Null));
    EXPECT_EQ(bs.wo, -si.wi);
    expectAlbedoNear(albedo(*bsdf, si, 20000), Color3f(0.5f + 0.5f * 0.5f));  // both sides alike
  }
}

// ---- null and mask -----------------------------------------------------

TEST(NullBSDF, PassesLightStraightThrough) {
  auto bsdf = make("null");
  EXPECT_EQ(bsdf->flags(), uint32_t(BSDFFlags::Null));
  SurfaceInteraction si = localInteraction({0.2f, 0.3f, -0.5f});
  BSDFSample bs;
  EXPECT_EQ(bsdf->sample(si, 0.7f, {0.1f, 0.9f}, bs), Color3f(1.0f));
  EXPECT_EQ(bs.wo, -si.wi);
  EXPECT_EQ(bs.sampledFlags, uint32_t(BSDFFlags::Null));
  EXPECT_EQ(bs.eta, 1.0f);
  EXPECT_GT(bs.pdf, 0.0f);
  EXPECT_TRUE(bsdf->eval(si, -si.wi).isBlack());
  EXPECT_EQ(bsdf->pdf(si, -si.wi), 0.0f);
}

TEST(MaskBSDF, BlendsPassThroughAndTheNestedBSDFByOpacity) {
  const float opacity = 0.3f;
  auto diffuse = makeDiffuse(Color3f(0.5f, 0.6f, 0.7f));
  auto mask = make("mask", [&](Properties& p) {
    p.setFloat("opacity", opacity);
    p.setObject("bsdf", diffuse);
  });
  EXPECT_EQ(mask->flags(), uint32_t(BSDFFlags::Null | BSDFFlags::DiffuseReflection));
  SurfaceInteraction si = localInteraction({0.3f, -0.2f, 0.8f});
  Vec3f wo = normalize(Vec3f(-0.1f, 0.4f, 0.5f));
  EXPECT_NEAR(mask->eval(si, wo).g, opacity * diffuse->eval(si, wo).g, 1e-6f);
  EXPECT_NEAR(mask->pdf(si, wo), opacity * diffuse->pdf(si, wo), 1e-6f);
  checkSampleEvalPdf(*mask, si, 2000);
  // Albedo: (1 - opacity) passes through unchanged, opacity scatters with the diffuse albedo.
  expectAlbedoNear(albedo(*mask, si, 40000), Color3f(1 - opacity) + Color3f(0.5f, 0.6f, 0.7f) * opacity);
  double smoothMass = 0;
  ChiSquareResult r = chiSquareSmoothLobes(*mask, si, smoothMass);
  EXPECT_GT(r.pValue, Significance) << r.message;
  EXPECT_NEAR(smoothMass, opacity, 2e-3);
}

// ---- bad parameters: errors name the scene file and line ---------------

TEST(SmoothBSDFErrors, BadValuesAreReportedWithFileAndLine) {
  auto expectError = [](const std::string& plugin, const std::function<void(Properties&)>& setup,
                        const std::string& where, const std::string& words) {
    std::string message = errorMessageOf([&] { make(plugin, setup); });
    EXPECT_NE(message.find(where), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  };
  for (const char* plugin : {"dielectric", "thindielectric", "plastic"}) {
    SCOPED_TRACE(plugin);
    expectError(plugin, [](Properties& p) { p.setFloat("int_ior", -1.5, Where); }, "scene.xml:12", "must be positive");
    expectError(plugin, [](Properties& p) { p.setFloat("ext_ior", 0.0, Where); }, "scene.xml:12", "must be positive");
    expectError(plugin, [](Properties& p) { p.setString("int_ior", "bk8", Where); }, "scene.xml:12",
                "unknown material \"bk8\"");
  }
  expectError("conductor", [](Properties& p) { p.setString("material", "Aux", Where); }, "scene.xml:12",
              "unknown conductor \"Aux\"");
  expectError("conductor", [](Properties& p) { p.setColor("eta", Color3f(-1.0f), Where); p.setColor("k", Color3f(1.0f)); },
              "scene.xml:12", "must not be negative");
  expectError("conductor", [](Properties& p) { p.setColor("eta", Color3f(1.0f), Where); }, "scene.xml:12",
              "eta and k must be given together");
  expectError("conductor", [](Properties& p) {
    p.setString("material", "Au", Where);
    p.setColor("eta", Color3f(1.0f));
    p.setColor("k", Color3f(1.0f));
  }, "scene.xml:12", "not both");
  expectError("plastic", [](Properties& p) { p.setColor("diffuse_reflectance", Color3f(-0.5f), Where); }, "scene.xml:12",
              "must not be negative");
  expectError("twosided", [](Properties&) {}, "scene.xml:3", "one or two nested <bsdf>, got 0");
  expectError("twosided", [](Properties& p) { p.setObject("_arg_0", make("dielectric")); }, "scene.xml:3",
              "cannot wrap a transmitting BSDF");
  expectError("mask", [](Properties&) {}, "scene.xml:3", "needs a nested <bsdf>");
  expectError("mask", [](Properties& p) { p.setFloat("opacity", 1.5, Where); p.setObject("b", makeDiffuse(Color3f(0.5f))); },
              "scene.xml:12", "must lie in [0, 1]");
}

TEST(ConductorBSDF, ExteriorIndexScalesTheOpticalConstants) {
  // Mitsuba 0.6's extEta (upgraded to ext_eta): a metal under water reflects less.
  const float water = *lookupIOR("water");
  auto inWater = make("conductor", [&](Properties& p) {
    p.setColor("eta", Color3f(water * 0.2f));
    p.setColor("k", Color3f(water * 3.0f));
    p.setString("ext_eta", "water");
  });
  BSDFSample bs;
  Color3f w = inWater->sample(localInteraction({0, 0, 1}), 0, {0, 0}, bs);
  EXPECT_NEAR(w.g, fresnelConductor(1.0f, Color3f(0.2f), Color3f(3.0f)).g, 1e-5f);
}
