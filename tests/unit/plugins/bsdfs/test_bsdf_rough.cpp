// Rough BSDF plugins: roughconductor, roughdielectric, roughplastic. Sampling
// is checked against pdf() by chi-square tests (including grazing incidence
// and transmission from both sides), sample weights against eval / pdf,
// reciprocity (and the adjoint relation of refraction), energy bounds in a
// white furnace, limits against smooth Fresnel closed forms, finite values at
// extreme roughness and angles, and the parameters of real scenes.
#include <gtest/gtest.h>

#include <filesystem>

#include <femto/math/warp.h>
#include <femto/render/bsdf.h>
#include <femto/scattering/fresnel.h>
#include <femto/xml/loader.h>

#include "chi2.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

/// A rough BSDF configuration: plugin name and parameters.
struct RoughCase {
  std::string plugin;
  std::string distribution;
  float alphaU, alphaV;  // alphaV < 0: isotropic (`alpha`)
  bool sampleVisible = true;
};

std::string describe(const RoughCase& c) {
  return str(c.plugin, " ", c.distribution, " alpha=(", c.alphaU, ", ", c.alphaV < 0 ? c.alphaU : c.alphaV, ")",
             c.sampleVisible ? "" : " all normals");
}

std::shared_ptr<BSDF> makeBSDF(const RoughCase& c, const std::function<void(Properties&)>& extra = {}) {
  Properties props(c.plugin);
  props.setString("distribution", c.distribution);
  if (c.alphaV < 0) {
    props.setFloat("alpha", c.alphaU);
  } else {
    props.setFloat("alpha_u", c.alphaU);
    props.setFloat("alpha_v", c.alphaV);
  }
  props.setBool("sample_visible", c.sampleVisible);
  if (extra) extra(props);
  return createPlugin<BSDF>(ObjectKind::BSDF, props);
}

Vec3f direction(float thetaDeg, float phiDeg) {
  float t = degToRad(thetaDeg), p = degToRad(phiDeg);
  return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

SurfaceInteraction localInteraction(const Vec3f& wi) {
  SurfaceInteraction si;
  si.n = Normal3f(0, 0, 1);
  si.wi = normalize(wi);
  return si;
}

// Relative index of the roughdielectric default (bk7 in air).
constexpr float Bk7 = 1.5046f / 1.000277f;

// Chi-square tests in this file, for the Sidak correction.
constexpr int ChiSquareTests = 3 * 3 + 3 * 4 + 2 * 3;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

/// Chi-square test of bsdf.sample() against bsdf.pdf() over the sphere of
/// outgoing directions; failed samples (pdf 0) are not counted. The theta
/// grid has lines at `breaks`, where the density jumps.
void expectSamplingMatchesPdf(const BSDF& bsdf, const Vec3f& wi, TransportMode mode = TransportMode::Radiance,
                              std::vector<double> breaks = {}) {
  SurfaceInteraction si = localInteraction(wi);
  PCG32 componentRng(11, 1);  // u1: the choice between lobes
  std::function<std::optional<Vec3f>(const Point2f&)> sample = [&](const Point2f& u) -> std::optional<Vec3f> {
    BSDFSample bs;
    bsdf.sample(si, componentRng.nextFloat(), u, bs, mode);
    if (!(bs.pdf > 0.0f)) return std::nullopt;
    return bs.wo;
  };
  std::function<double(const Vec3f&)> pdf = [&](const Vec3f& wo) { return bsdf.pdf(si, wo, mode); };
  breaks.push_back(0.5 * Pi);  // the horizon
  ChiSquareResult r =
      testSamplerAllowingFailures<Vec3f>(sphericalDomainWithBreaks(breaks, 48, 96), sample, pdf, 200000, 6);
  EXPECT_GT(r.pValue, Significance) << r.message;
}

/// Mean and standard error of the sample weights (f cos / pdf) of `n`
/// samples: an unbiased estimate of the directional albedo, channel 0.
std::pair<double, double> albedo(const BSDF& bsdf, const Vec3f& wi, TransportMode mode, int n = 100000,
                                 uint32_t onlyFlags = ~0u) {
  SurfaceInteraction si = localInteraction(wi);
  PCG32 rng(5, 1);
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < n; ++k) {
    BSDFSample bs;
    Color3f w = bsdf.sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs, mode);
    double x = bs.pdf > 0.0f && (bs.sampledFlags & onlyFlags) ? w.r : 0.0;
    sum += x;
    sum2 += x * x;
  }
  double mean = sum / n, variance = std::max(0.0, sum2 / n - mean * mean);
  return {mean, std::sqrt(variance / n)};
}

const RoughCase Conductors[] = {
    {"roughconductor", "beckmann", 0.2f, -1},
    {"roughconductor", "ggx", 0.1f, 0.4f},
    {"roughconductor", "ggx", 0.5f, -1, false},
};
const RoughCase Dielectrics[] = {
    {"roughdielectric", "beckmann", 0.2f, -1},
    {"roughdielectric", "ggx", 0.5f, 0.25f},
    {"roughdielectric", "beckmann", 0.4f, -1, false},
};
const RoughCase Plastics[] = {
    {"roughplastic", "beckmann", 0.1f, -1},
    {"roughplastic", "ggx", 0.4f, -1},
};

std::vector<std::shared_ptr<BSDF>> allRoughBSDFs() {
  std::vector<std::shared_ptr<BSDF>> out;
  for (const auto& c : Conductors) out.push_back(makeBSDF(c, [](Properties& p) { p.setString("material", "Au"); }));
  for (const auto& c : Dielectrics) out.push_back(makeBSDF(c));
  for (const auto& c : Plastics) out.push_back(makeBSDF(c));
  return out;
}

}  // namespace

TEST(RoughConductor, SamplingMatchesItsPdf) {
  for (const RoughCase& c : Conductors)
    for (const Vec3f& wi : {direction(0, 0), direction(45, 20), direction(85, 120)}) {
      SCOPED_TRACE(str(describe(c), " wi=", wi));
      expectSamplingMatchesPdf(*makeBSDF(c), wi);
    }
}

namespace {

void expectDielectricSamplingMatchesPdf(std::initializer_list<Vec3f> incident) {
  for (const RoughCase& c : Dielectrics)
    for (const Vec3f& wi : incident) {
      SCOPED_TRACE(str(describe(c), " wi=", wi));
      // Refraction through a microfacet with m.z > 0 needs wi.z + eta_t wo.z
      // < 0 (the generalised half vector points down): the refracted lobe
      // ends abruptly at wo.z = -wi.z / eta_t, where grazing microfacets
      // refract.
      float etaT = wi.z > 0 ? Bk7 : 1.0f / Bk7;
      std::vector<double> breaks;
      if (std::abs(wi.z / etaT) < 1.0f) breaks.push_back(std::acos(-wi.z / etaT));
      expectSamplingMatchesPdf(*makeBSDF(c), wi, wi.z > 0 ? TransportMode::Radiance : TransportMode::Importance,
                               breaks);
    }
}

}  // namespace

TEST(RoughDielectric, SamplingMatchesItsPdfFromOutside) {
  expectDielectricSamplingMatchesPdf({direction(30, 10), direction(80, 250)});
}

TEST(RoughDielectric, SamplingMatchesItsPdfFromInside) {
  // Below and above the critical angle (41.6 degrees for bk7).
  expectDielectricSamplingMatchesPdf({-direction(20, 60), -direction(60, 300)});
}

TEST(RoughPlastic, SamplingMatchesItsPdf) {
  for (const RoughCase& c : Plastics)
    for (const Vec3f& wi : {direction(0, 0), direction(40, 30), direction(85, 200)}) {
      SCOPED_TRACE(str(describe(c), " wi=", wi));
      expectSamplingMatchesPdf(*makeBSDF(c, [](Properties& p) { p.setColor("diffuse_reflectance", Color3f(0.3f)); }),
                               wi);
    }
}

TEST(RoughBSDFs, SampleWeightIsEvalOverPdf) {
  PCG32 rng(7, 1);
  for (const auto& bsdf : allRoughBSDFs())
    for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance})
      for (const Vec3f& wi : {direction(35, 40), direction(75, 190), -direction(30, 100)}) {
        SCOPED_TRACE(str(bsdf->toString(), " wi=", wi));
        SurfaceInteraction si = localInteraction(wi);
        int succeeded = 0;
        for (int k = 0; k < 300; ++k) {
          BSDFSample bs;
          Color3f weight = bsdf->sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs, mode);
          if (!(bs.pdf > 0.0f)) {
            EXPECT_TRUE(weight.isBlack());
            continue;
          }
          ++succeeded;
          float pdf = bsdf->pdf(si, bs.wo, mode);
          Color3f f = bsdf->eval(si, bs.wo, mode);
          ASSERT_NEAR(pdf, bs.pdf, 2e-3f * pdf);
          for (int ch = 0; ch < 3; ++ch) ASSERT_NEAR(weight[ch], f[ch] / pdf, 2e-3f * f[ch] / pdf + 1e-6f);
          EXPECT_TRUE(bs.sampledFlags & bsdf->flags());
        }
        if (wi.z > 0 || bsdf->flags() & BSDFFlags::Transmission) EXPECT_GT(succeeded, 100);
      }
}

TEST(RoughBSDFs, AreReciprocal) {
  // f(wi, wo) = f(wo, wi) for reflection. For refraction the BSDF for
  // radiance satisfies f(wo, wi) = eta_t^2 f(wi, wo) (eta_t: the index ratio
  // seen from wi), and its adjoint, the BSDF for importance, is the
  // transpose: f_importance(wo, wi) = f_radiance(wi, wo) (Veach 1997, sec. 5.2).
  PCG32 rng(9, 1);
  for (const auto& bsdf : allRoughBSDFs()) {
    SCOPED_TRACE(bsdf->toString());
    bool dielectric = (bsdf->flags() & BSDFFlags::Transmission) != 0;
    int compared = 0;
    for (int k = 0; k < 2000; ++k) {
      Vec3f wi = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()});
      Vec3f wo = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()});
      auto f = [&](const Vec3f& a, const Vec3f& b, TransportMode mode) {
        return bsdf->eval(localInteraction(a), b, mode).r / std::abs(b.z);
      };
      float forward = f(wi, wo, TransportMode::Radiance), backward = f(wo, wi, TransportMode::Radiance);
      if (!(forward > 1e-4f)) continue;
      float etaT = wi.z * wo.z > 0 ? 1.0f : (wi.z > 0 ? Bk7 : 1.0f / Bk7);
      // Near the critical angle on the microfacet, F has an infinite slope:
      // the float round-off of either cosine changes F by more than 1e-3.
      Vec3f m = normalize(wi + wo * etaT);
      float cosInside = std::abs(dot(wi.z < 0 ? wi : wo, m)), cosCritical = std::sqrt(1 - 1 / (Bk7 * Bk7));
      if (etaT != 1.0f && std::abs(cosInside - cosCritical) < 1e-3f) continue;
      ++compared;
      ASSERT_NEAR(backward, etaT * etaT * forward, 1e-3f * backward) << "wi=" << wi << " wo=" << wo;
      if (dielectric) ASSERT_NEAR(f(wo, wi, TransportMode::Importance), forward, 1e-3f * forward);
    }
    EXPECT_GT(compared, 50);
  }
}

TEST(RoughBSDFs, WhiteFurnaceDoesNotCreateEnergy) {
  // Albedo with every reflectance 1 (a perfect-mirror conductor) is at most
  // 1: separable Smith masking loses energy, it never adds it. For refraction
  // this holds for the importance BSDF (radiance is scaled by eta^2).
  auto fromNone = [](Properties& p) { p.setString("material", "none"); };
  auto whitePlastic = [](Properties& p) { p.setColor("diffuse_reflectance", Color3f(1.0f)); };
  for (float alpha : {0.05f, 0.3f, 0.8f})
    for (const char* distribution : {"beckmann", "ggx"})
      for (const Vec3f& wi : {direction(10, 0), direction(60, 30), direction(88, 80), -direction(50, 10)}) {
        std::vector<std::pair<std::string, std::shared_ptr<BSDF>>> bsdfs = {
            {"roughconductor", makeBSDF({"roughconductor", distribution, alpha, -1}, fromNone)},
            {"roughdielectric", makeBSDF({"roughdielectric", distribution, alpha, -1})},
            {"roughplastic", makeBSDF({"roughplastic", distribution, alpha, -1}, whitePlastic)},
        };
        for (const auto& [name, bsdf] : bsdfs) {
          if (wi.z < 0 && name != "roughdielectric") continue;
          auto [mean, error] = albedo(*bsdf, wi, TransportMode::Importance, 10000);
          SCOPED_TRACE(str(name, " ", distribution, " alpha=", alpha, " wi=", wi, " albedo=", mean, " +- ", error));
          EXPECT_LE(mean, 1.0 + 4.0 * error + 1e-4);
          EXPECT_GT(mean, 0.3);  // rough GGX at alpha 0.8 reflects 40% of the normals below the horizon
        }
      }
}

TEST(RoughBSDFs, NearlySmoothSurfacesMatchFresnel) {
  // At alpha = 0.01 and normal incidence the rough models reduce to a smooth
  // interface: the conductor reflects the Fresnel reflectance, the
  // dielectric reflects F and refracts 1 - F (importance BSDF).
  Vec3f wi = direction(5, 0);
  auto conductor = makeBSDF({"roughconductor", "ggx", 0.01f, -1}, [](Properties& p) {
    p.setColor("eta", Color3f(0.2f, 0.9f, 1.1f));
    p.setColor("k", Color3f(3.9f, 2.4f, 1.8f));
  });
  auto [reflected, error] = albedo(*conductor, wi, TransportMode::Radiance, 20000);
  EXPECT_NEAR(reflected, fresnelConductor(wi.z, Color3f(0.2f), Color3f(3.9f)).r, 2e-3 + 4 * error);

  auto dielectric = makeBSDF({"roughdielectric", "beckmann", 0.01f, -1}, [](Properties& p) { p.setFloat("int_ior", 1.7); });
  float F = fresnelDielectric(wi.z, 1.7f / 1.000277f);
  auto [r, rError] = albedo(*dielectric, wi, TransportMode::Importance, 40000, BSDFFlags::GlossyReflection);
  auto [t, tError] = albedo(*dielectric, wi, TransportMode::Importance, 40000, BSDFFlags::GlossyTransmission);
  EXPECT_NEAR(r, F, 2e-3 + 4 * rError);
  EXPECT_NEAR(t, 1.0 - F, 2e-3 + 4 * tError);
}

TEST(RoughPlastic, CoatingIsTheRoughDielectricsReflectionAndDiffusePartMatchesSmoothPlastic) {
  // With a black base, roughplastic is the reflection of roughdielectric.
  RoughCase c{"roughplastic", "ggx", 0.3f, -1};
  auto black = makeBSDF(c, [](Properties& p) {
    p.setColor("diffuse_reflectance", Color3f(0.0f));
    p.setFloat("int_ior", 1.5);
  });
  auto dielectric = makeBSDF({"roughdielectric", "ggx", 0.3f, -1}, [](Properties& p) { p.setFloat("int_ior", 1.5); });
  PCG32 rng(13, 1);
  for (int k = 0; k < 200; ++k) {
    Vec3f wi = warp::squareToUniformHemisphere({rng.nextFloat(), rng.nextFloat()});
    Vec3f wo = warp::squareToUniformHemisphere({rng.nextFloat(), rng.nextFloat()});
    float expected = dielectric->eval(localInteraction(wi), wo).r;
    EXPECT_NEAR(black->eval(localInteraction(wi), wo).r, expected, 1e-5f + 1e-4f * expected);
  }
  // Away from the mirror direction a nearly smooth coating leaves the
  // diffuse term of smooth plastic: rho (1 - F(i)) (1 - F(o)) cos(o) /
  // (pi eta^2 (1 - F_dr,int)), with F_dr,int the hemispherical average of the
  // internal Fresnel reflectance (fresnelDiffuseReflectance, a fit good to
  // about 1%).
  float eta = 1.5f;
  auto smooth = makeBSDF({"roughplastic", "beckmann", 0.001f, -1}, [&](Properties& p) {
    p.setColor("diffuse_reflectance", Color3f(0.6f));
    p.setFloat("int_ior", eta);
    p.setFloat("ext_ior", 1.0);
  });
  float fdrInternal = fresnelDiffuseReflectance(1.0f / eta);
  for (const auto& [wi, wo] : {std::pair{direction(20, 0), direction(50, 90)}, {direction(70, 10), direction(5, 250)},
                               {direction(45, 0), direction(80, 0)}}) {
    float expected = 0.6f * (1 - fresnelDielectric(wi.z, eta)) * (1 - fresnelDielectric(wo.z, eta)) * wo.z /
                     (Pi * eta * eta * (1 - fdrInternal));
    EXPECT_NEAR(smooth->eval(localInteraction(wi), wo).r, expected, 0.02f * expected) << "wi=" << wi << " wo=" << wo;
  }
}

TEST(RoughBSDFs, StayFiniteAtTinyRoughnessAndGrazingAngles) {
  PCG32 rng(17, 1);
  for (const char* plugin : {"roughconductor", "roughdielectric", "roughplastic"})
    for (const char* distribution : {"beckmann", "ggx"})
      for (float alpha : {1e-3f, 1e-6f, 1.0f}) {
        auto bsdf = makeBSDF({plugin, distribution, alpha, -1});
        for (float cosTheta : {1.0f, 1e-3f, 1e-6f, 0.0f, -1e-6f, -1e-3f}) {
          SCOPED_TRACE(str(plugin, " ", distribution, " alpha=", alpha, " cos=", cosTheta));
          SurfaceInteraction si = localInteraction({std::sqrt(1 - cosTheta * cosTheta), 0, cosTheta});
          for (int k = 0; k < 200; ++k) {
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
              BSDFSample bs;
              Color3f w = bsdf->sample(si, rng.nextFloat(), {rng.nextFloat(), rng.nextFloat()}, bs, mode);
              ASSERT_TRUE(w.isValid()) << w;
              ASSERT_TRUE(std::isfinite(bs.pdf) && bs.pdf >= 0.0f) << bs.pdf;
              // Grazing and random outgoing directions, and the mirror direction.
              float c = k % 3 == 0 ? 1e-6f * (rng.nextFloat() - 0.5f) : 2.0f * rng.nextFloat() - 1.0f;
              float phi = 2 * Pi * rng.nextFloat(), s = std::sqrt(1 - c * c);
              for (const Vec3f& wo : {Vec3f(s * std::cos(phi), s * std::sin(phi), c), reflect(si.wi, Vec3f(0, 0, 1))}) {
                ASSERT_TRUE(bsdf->eval(si, wo, mode).isValid()) << wo;
                float pdf = bsdf->pdf(si, wo, mode);
                ASSERT_TRUE(std::isfinite(pdf) && pdf >= 0.0f) << pdf << " wo=" << wo;
              }
            }
          }
        }
      }
}

TEST(RoughConductor, ExteriorIndexLowersTheReflectance) {
  // Mitsuba 0.6's extEta: gold under water reflects less than gold in air.
  auto gold = [](const char* exterior) {
    return makeBSDF({"roughconductor", "ggx", 0.2f, -1}, [&](Properties& p) {
      p.setString("material", "Au");
      if (exterior) p.setString("ext_eta", exterior);
    });
  };
  SurfaceInteraction si = localInteraction(direction(30, 0));
  Vec3f wo = direction(30, 180);
  Color3f inAir = gold(nullptr)->eval(si, wo), underWater = gold("water")->eval(si, wo);
  for (int c = 0; c < 3; ++c) EXPECT_LT(underWater[c], inAir[c]);
}

TEST(RoughBSDFs, BadParametersAreReportedAtTheirLine) {
  auto at = [](int line) { return SourceLocation{"scene.xml", line}; };
  Properties both("roughconductor");
  both.setString("material", "Au", at(3));
  both.setColor("eta", Color3f(0.2f), at(4));
  std::string message = errorMessageOf([&] { createPlugin<BSDF>(ObjectKind::BSDF, both); });
  EXPECT_NE(message.find("scene.xml:3"), std::string::npos) << message;

  Properties lone("roughconductor");
  lone.setColor("eta", Color3f(0.2f), at(8));
  message = errorMessageOf([&] { createPlugin<BSDF>(ObjectKind::BSDF, lone); });
  EXPECT_NE(message.find("scene.xml:8"), std::string::npos) << message;
  EXPECT_NE(message.find("together"), std::string::npos) << message;

  Properties unknown("roughconductor");
  unknown.setString("material", "Gold", at(5));
  message = errorMessageOf([&] { createPlugin<BSDF>(ObjectKind::BSDF, unknown); });
  EXPECT_NE(message.find("scene.xml:5"), std::string::npos) << message;
  EXPECT_NE(message.find("\"Gold\""), std::string::npos) << message;

  Properties matched("roughdielectric");
  matched.setFloat("int_ior", 1.333, at(6));
  matched.setString("ext_ior", "water", at(7));
  message = errorMessageOf([&] { createPlugin<BSDF>(ObjectKind::BSDF, matched); });
  EXPECT_NE(message.find("scene.xml:6"), std::string::npos) << message;

  Properties glass("roughdielectric");
  glass.setString("int_ior", "bk7", at(6));
  EXPECT_NE(createPlugin<BSDF>(ObjectKind::BSDF, glass)->toString().find("eta=1.50"), std::string::npos);
}

TEST(RoughPlastic, LoadsVeachMisPlatesFromAMitsuba04SceneInStrictMode) {
  // The plates of lajolla-veach-mis-0.4/mi.xml, as written there (0.4 names).
  const char* xml = R"(<bsdf type="roughplastic" version="0.4.0">
  <rgb name="diffuseReflectance" value="0.07 0.09 0.13"/>
  <spectrum name="specularReflectance" value="1"/>
  <float name="intIOR" value="2"/>
  <float name="alpha" value="0.005"/>
</bsdf>)";
  LoadOptions strict;
  strict.strict = true;
  ObjectRef plate = loadObjectFromString(xml, std::filesystem::temp_directory_path(), strict, "plates.xml");
  std::string text = plate->toString();
  EXPECT_NE(text.find("eta=1.99945"), std::string::npos) << text;  // 2 / air
  EXPECT_NE(text.find("alpha_u=0.005"), std::string::npos) << text;
  EXPECT_NE(text.find("type=beckmann"), std::string::npos) << text;
  EXPECT_NE(text.find("0.07, 0.09, 0.13"), std::string::npos) << text;

  // An anisotropic roughness is not something roughplastic reads: strict mode refuses it.
  const char* aniso = R"(<bsdf version="3.0.0" type="roughplastic">
  <float name="alpha_u" value="0.1"/>
</bsdf>)";
  std::string error = errorMessageOf([&] { loadObjectFromString(aniso, ".", strict, "aniso.xml"); });
  EXPECT_NE(error.find("aniso.xml:2"), std::string::npos) << error;
  EXPECT_NE(error.find("alpha_u"), std::string::npos) << error;
}

TEST(RoughPlastic, TheWholeVeachMisSceneLoadsInStrictMode) {
  std::filesystem::path file = "/work/shared/scenes/lajolla-veach-mis-0.4/mi.xml";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared scene corpus";
  std::vector<std::string> available = PluginManager::instance().availableNames();
  for (const char* name : {"direct", "ldsampler", "gaussian", "hdrfilm", "perspective", "sphere", "obj", "area"})
    if (std::find(available.begin(), available.end(), name) == available.end())
      GTEST_SKIP() << "plugin " << name << " is not built yet";
  LoadOptions strict;
  strict.strict = true;
  strict.resolution = Point2i(8, 8);
  strict.sampleCount = 1;
  EXPECT_NO_THROW(loadScene(file, strict));
}
