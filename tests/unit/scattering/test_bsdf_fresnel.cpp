// Fresnel functions of scattering/fresnel.h against values derived by hand from
// the Fresnel equations, and the diffuse-reflectance fit against numerical
// integration.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/constants.h>
#include <femto/math/frame.h>
#include <femto/scattering/fresnel.h>

using namespace femto;

namespace {

/// Normal-incidence reflectance ((n - 1) / (n + 1))^2 (Born & Wolf 1.5.2).
float normalIncidence(float eta) { return (eta - 1) * (eta - 1) / ((eta + 1) * (eta + 1)); }

/// s-polarised reflectance alone, written from Snell's law with angles (an
/// independent form of the same equations: rs = -sin(i - t) / sin(i + t)).
double rsFromAngles(double thetaI, double eta) {
  double thetaT = std::asin(std::sin(thetaI) / eta);
  double rs = std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
  return rs * rs;
}
/// p-polarised: rp = tan(i - t) / tan(i + t).
double rpFromAngles(double thetaI, double eta) {
  double thetaT = std::asin(std::sin(thetaI) / eta);
  double rp = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
  return rp * rp;
}

}  // namespace

TEST(Fresnel, DielectricAtNormalIncidence) {
  for (float eta : {1.1f, 1.33f, 1.5f, 2.4f}) {
    float cosT = 0;
    EXPECT_NEAR(fresnelDielectric(1.0f, eta, cosT), normalIncidence(eta), 1e-6f) << eta;
    EXPECT_FLOAT_EQ(cosT, -1.0f);
    // From the inside the normal-incidence value is the same.
    EXPECT_NEAR(fresnelDielectric(-1.0f, eta, cosT), normalIncidence(eta), 1e-6f) << eta;
    EXPECT_FLOAT_EQ(cosT, 1.0f);
  }
  EXPECT_FLOAT_EQ(fresnelDielectric(0.7f, 1.0f), 0.0f);  // index-matched: no reflection
}

TEST(Fresnel, DielectricMatchesAngleFormsAndBrewster) {
  const double eta = 1.5;
  for (double deg : {10.0, 30.0, 45.0, 60.0, 80.0}) {
    double theta = deg * Pi / 180.0;
    double expected = 0.5 * (rsFromAngles(theta, eta) + rpFromAngles(theta, eta));
    EXPECT_NEAR(fresnelDielectric(float(std::cos(theta)), float(eta)), expected, 2e-5) << deg;
  }
  // At Brewster's angle p-light is not reflected, so R = Rs / 2.
  double brewster = std::atan(eta);
  EXPECT_NEAR(fresnelDielectric(float(std::cos(brewster)), float(eta)), 0.5 * rsFromAngles(brewster, eta), 2e-6);
  EXPECT_LT(rpFromAngles(brewster, eta), 1e-12);  // the closed form used above is itself right
}

TEST(Fresnel, TotalInternalReflection) {
  const float eta = 1.5f;
  const float critical = std::asin(1.0f / eta);
  float cosT = 5.0f;
  EXPECT_EQ(fresnelDielectric(-std::cos(critical + 0.01f), eta, cosT), 1.0f);
  EXPECT_EQ(cosT, 0.0f);
  // Just inside the critical angle light is still transmitted, at a grazing angle.
  float r = fresnelDielectric(-std::cos(critical - 0.01f), eta, cosT);
  EXPECT_LT(r, 1.0f);
  EXPECT_GT(cosT, 0.0f);
  EXPECT_LT(cosT, 0.25f);
}

TEST(Fresnel, ReflectanceIsTheSameBothWaysAcross) {
  // Stokes relations: R is symmetric between an incident ray and its refracted ray.
  for (float cosI : {0.9f, 0.5f, 0.2f}) {
    float cosT;
    float r1 = fresnelDielectric(cosI, 1.5f, cosT);
    float cosBack;
    float r2 = fresnelDielectric(cosT, 1.5f, cosBack);
    EXPECT_NEAR(r1, r2, 1e-5f);
    EXPECT_NEAR(cosBack, cosI, 1e-5f);  // back out along the incident direction
  }
}

TEST(Fresnel, RefractObeysSnellAndIsReversible) {
  const float eta = 1.5f;
  Vec3f wi = normalize(Vec3f(0.4f, -0.3f, 0.6f));
  float cosT;
  fresnelDielectric(wi.z, eta, cosT);
  Vec3f wt = refract(wi, cosT, eta);
  EXPECT_NEAR(length(wt), 1.0f, 1e-5f);
  EXPECT_LT(wt.z, 0.0f);
  // sin(i) = eta sin(t), and the refracted ray lies in the plane of incidence, opposite side.
  EXPECT_NEAR(Frame::sinTheta(wi), eta * Frame::sinTheta(wt), 1e-5f);
  EXPECT_NEAR(wt.x * wi.y - wt.y * wi.x, 0.0f, 1e-6f);
  EXPECT_LT(wt.x * wi.x, 0.0f);
  // Refracting back out gives the original direction.
  float cosBack;
  fresnelDielectric(wt.z, eta, cosBack);
  Vec3f back = refract(wt, cosBack, eta);
  EXPECT_NEAR(back.x, wi.x, 1e-5f);
  EXPECT_NEAR(back.y, wi.y, 1e-5f);
  EXPECT_NEAR(back.z, wi.z, 1e-5f);
  // The general-normal form agrees with the +z form for m = +z.
  Vec3f wm = refract(wi, Vec3f(0, 0, 1), cosT, eta);
  EXPECT_NEAR(wm.x, wt.x, 1e-6f);
  EXPECT_NEAR(wm.y, wt.y, 1e-6f);
  EXPECT_NEAR(wm.z, wt.z, 1e-6f);
}

TEST(Fresnel, ConductorClosedForms) {
  // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2).
  Color3f n(0.2f, 1.0f, 2.5f), k(3.0f, 2.0f, 0.0f);
  Color3f r = fresnelConductor(1.0f, n, k);
  for (int c = 0; c < 3; ++c) {
    float expected = ((n[c] - 1) * (n[c] - 1) + k[c] * k[c]) / ((n[c] + 1) * (n[c] + 1) + k[c] * k[c]);
    EXPECT_NEAR(r[c], expected, 1e-5f);
  }
  // With k = 0 the conductor formula is the dielectric one (entering from outside).
  for (float cosI : {0.95f, 0.6f, 0.3f, 0.05f}) {
    EXPECT_NEAR(fresnelConductor(cosI, Color3f(1.7f), Color3f(0.0f)).r, fresnelDielectric(cosI, 1.7f), 1e-5f);
  }
  // Grazing incidence reflects everything; "none" is a perfect mirror at every angle.
  EXPECT_NEAR(fresnelConductor(0.0f, n, k).g, 1.0f, 1e-5f);
  auto mirror = lookupConductor("none");
  ASSERT_TRUE(mirror.has_value());
  for (float cosI : {1.0f, 0.5f, 0.01f}) EXPECT_NEAR(fresnelConductor(cosI, mirror->first, mirror->second).b, 1.0f, 1e-6f);
}

TEST(Fresnel, ConductorTableIsPlausible) {
  // Normal-incidence reflectances of well-known metals (each within a few percent of handbook values).
  auto reflectance = [](const char* name) {
    auto nk = lookupConductor(name);
    EXPECT_TRUE(nk.has_value()) << name;
    return nk ? fresnelConductor(1.0f, nk->first, nk->second) : Color3f(0.0f);
  };
  Color3f au = reflectance("Au"), ag = reflectance("Ag"), al = reflectance("Al"), cu = reflectance("Cu");
  EXPECT_GT(au.r, 0.9f);
  EXPECT_LT(au.b, 0.5f);  // gold is yellow
  EXPECT_GT(ag.g, 0.9f);
  EXPECT_NEAR(al.g, 0.92f, 0.03f);
  EXPECT_GT(cu.r, cu.g);
  for (const std::string& name : knownConductorNames()) {
    Color3f r = reflectance(name.c_str());
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(r[c], 0.3f) << name;
      EXPECT_LE(r[c], 1.0f) << name;
    }
  }
  EXPECT_FALSE(lookupConductor("unobtainium").has_value());
}

TEST(Fresnel, DiffuseReflectanceFitMatchesIntegral) {
  for (float eta : {1.0f / 1.8f, 1.0f / 1.5f, 1.0f / 1.33f, 1.2f, 1.33f, 1.5f, 1.8f}) {
    // 2 * integral_0^1 R(mu) mu dmu by the midpoint rule.
    const int n = 20000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      double mu = (i + 0.5) / n;
      sum += fresnelDielectric(float(mu), eta) * mu;
    }
    double integral = 2.0 * sum / n;
    EXPECT_NEAR(fresnelDiffuseReflectance(eta), integral, 0.01 * integral + 1e-4) << eta;
  }
}
