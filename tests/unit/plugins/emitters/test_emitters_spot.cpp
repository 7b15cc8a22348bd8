// The spot emitter: Mitsuba's falloff (full intensity inside beam_width,
// linear in angle to zero at cutoff_angle), emitted rays checked against the
// cone density with a chi-square test, and power against a numerical
// integral of the intensity.
#include <gtest/gtest.h>

#include <numeric>

#include <femto/math/warp.h>
#include <femto/render/emitter.h>

#include "chi2.h"
#include "expect_color.h"
#include "render_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int ChiSquareTests = 1;
const double Significance = sidakSignificance(0.01, ChiSquareTests);

const Point3f Position(0.5f, -1.0f, 2.0f);
const Color3f Intensity(1.0f, 2.0f, 4.0f);

/// A spot at Position pointing straight down (-z).
std::shared_ptr<Emitter> makeSpot(float cutoff = -1.0f, float beam = -1.0f) {
  Properties props("spot");
  props.setColor("intensity", Intensity);
  props.setTransform("to_world", Transform::translate(Position) * Transform::rotate({1, 0, 0}, 180.0f));
  if (cutoff > 0.0f) props.setFloat("cutoff_angle", cutoff);
  if (beam >= 0.0f) props.setFloat("beam_width", beam);
  return makePlugin<Emitter>(ObjectKind::Emitter, props);
}

/// World direction at `angleDeg` from the spot's axis (-z), tilted toward `azimuthDeg`.
Vec3f directionAt(float angleDeg, float azimuthDeg = 30.0f) {
  float t = degToRad(angleDeg), p = degToRad(azimuthDeg);
  return Vec3f(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), -std::cos(t));
}

/// Intensity toward `d`, measured as sampleDirection's value times distance squared.
Color3f intensityToward(const Emitter& spot, const Vec3f& d, float dist = 3.0f) {
  DirectionSample ds;
  Color3f value = spot.sampleDirection(Position + d * dist, {0.5f, 0.5f}, ds);
  EXPECT_TRUE(ds.delta);
  EXPECT_NEAR(ds.dist, dist, 1e-5f);
  EXPECT_NEAR(dot(ds.d, -d), 1.0f, 1e-5f);
  return value * (ds.dist * ds.dist);
}

}  // namespace

TEST(SpotLight, FalloffIsFlatInsideTheBeamAndLinearInAngleToTheCutoff) {
  // Defaults: cutoff 20 degrees, beam width 3/4 of it = 15.
  auto spot = makeSpot();
  for (float angle : {0.0f, 5.0f, 14.9f}) expectColorNear(intensityToward(*spot, directionAt(angle)), Intensity, 1e-4f);
  expectColorNear(intensityToward(*spot, directionAt(17.5f)), Intensity * 0.5f, 1e-4f);
  expectColorNear(intensityToward(*spot, directionAt(19.0f)), Intensity * 0.2f, 1e-4f);
  for (float angle : {20.1f, 45.0f, 90.0f, 150.0f}) EXPECT_TRUE(intensityToward(*spot, directionAt(angle)).isBlack());

  auto wide = makeSpot(40.0f, 10.0f);
  expectColorNear(intensityToward(*wide, directionAt(10.0f, 200.0f)), Intensity, 1e-4f);
  expectColorNear(intensityToward(*wide, directionAt(25.0f, 200.0f)), Intensity * 0.5f, 1e-4f);
  expectColorNear(intensityToward(*wide, directionAt(32.5f, 200.0f)), Intensity * 0.25f, 1e-4f);
  EXPECT_TRUE(intensityToward(*wide, directionAt(40.5f, 200.0f)).isBlack());
}

TEST(SpotLight, InverseSquareLawAndDeltaPdf) {
  auto spot = makeSpot();
  Color3f near = intensityToward(*spot, directionAt(5.0f), 1.0f), far = intensityToward(*spot, directionAt(5.0f), 7.0f);
  expectColorNear(near, far, 1e-4f);
  DirectionSample ds;
  spot->sampleDirection(Position + directionAt(5.0f) * 2.0f, {0.1f, 0.9f}, ds);
  EXPECT_EQ(ds.pdf, 1.0f);
  EXPECT_EQ(spot->pdfDirection(Position, ds), 0.0f);  // a delta light is never hit by chance
  EXPECT_TRUE(spot->isDelta());
}

TEST(SpotLight, EmittedRaysFollowTheConeDensityAndCarryTheIntensity) {
  auto spot = makeSpot(30.0f, 12.0f);
  const float cosCutoff = std::cos(degToRad(30.0f));
  auto conePdf = [&](const Vec3f& d) -> double {
    return warp::squareToUniformConePdf(Vec3f(d.x, -d.y, -d.z), cosCutoff);  // rotate(x, 180) maps -z to +z
  };
  std::function<Vec3f(const Point2f&)> sample = [&](const Point2f& u) {
    Ray ray;
    spot->sampleRay({0.3f, 0.7f}, u, ray);
    EXPECT_NEAR(distance(ray.o, Position), 0.0f, 1e-5f);
    return ray.d;
  };
  std::function<double(const Vec3f&)> pdf = conePdf;
  // 5-degree cells in theta: the cutoff (150 degrees from +z) lies on a cell edge.
  ChiSquareResult r = testSampler<Vec3f>(sphericalDomain(36, 36), sample, pdf, 500000, 16);
  EXPECT_GT(r.pValue, Significance) << r.message;
  // Each ray's weight is the intensity in its direction over the cone density.
  PCG32 rng(3, 5);
  for (int i = 0; i < 200; ++i) {
    Ray ray;
    Color3f weight = spot->sampleRay({rng.nextFloat(), rng.nextFloat()}, {rng.nextFloat(), rng.nextFloat()}, ray);
    expectColorNear(weight * float(conePdf(ray.d)), intensityToward(*spot, ray.d), 1e-3f);
  }
}

TEST(SpotLight, PowerIsTheIntensityIntegratedOverTheSphere) {
  for (auto [cutoff, beam] : {std::pair{20.0f, -1.0f}, std::pair{40.0f, 10.0f}, std::pair{30.0f, 30.0f}}) {
    SCOPED_TRACE(str("cutoff ", cutoff, ", beam ", beam));
    auto spot = makeSpot(cutoff, beam);
    GridDomain<Vec3f> domain = sphericalDomain(400, 8);
    std::function<double(const Vec3f&)> blue = [&](const Vec3f& d) { return intensityToward(*spot, d)[2]; };
    std::vector<double> cells = integrateCells(domain, blue, 8);
    double integral = std::accumulate(cells.begin(), cells.end(), 0.0);
    EXPECT_NEAR(spot->power()[2], integral, 2e-3 * integral);
    EXPECT_NEAR(spot->power()[0] * Intensity[2], spot->power()[2] * Intensity[0], 1e-4f * spot->power()[2]);
  }
}

TEST(SpotLight, BadAnglesAreErrors) {
  Properties props("spot");
  props.setFloat("cutoff_angle", 120.0f);
  EXPECT_THROW(makePlugin<Emitter>(ObjectKind::Emitter, props), Error);
  Properties beam("spot");
  beam.setFloat("beam_width", -3.0f);
  EXPECT_THROW(makePlugin<Emitter>(ObjectKind::Emitter, beam), Error);
}
