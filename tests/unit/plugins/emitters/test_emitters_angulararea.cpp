// mitransient's angulararea emitter: an area light with a spot's angular
// falloff around the normal. Falloff and its (projected) solid angles against
// numerical integrals, eval and next-event estimation consistent, emitted
// rays carrying the power on average, and the wide-open cone equal to `area`.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/lights/cone_falloff.h>
#include <femto/render/emitter.h>
#include <femto/render/shape.h>
#include <femto/xml/loader.h>

#include "expect_color.h"

using namespace femto;
using femto::test::expectColorNear;

namespace {

const Color3f Radiance(1.0f, 2.0f, 3.0f);

/// A 2x2 rectangle in the z = 0 plane facing +z, emitting with angulararea
/// (or `type`) and the given extra parameters.
std::shared_ptr<Shape> lamp(const std::string& parameters, const std::string& type = "angulararea") {
  std::string xml = "<shape type=\"rectangle\"><emitter type=\"" + type +
                    "\"><rgb name=\"radiance\" value=\"1, 2, 3\"/>" + parameters + "</emitter></shape>";
  return std::dynamic_pointer_cast<Shape>(loadObjectFromString(xml, ".", {}, "lamp.xml"));
}

ConeFalloff falloffOf(float cutoffDeg, float beamDeg) {
  Properties props("angulararea");
  props.setFloat("cutoff_angle", cutoffDeg);
  props.setFloat("beam_width", beamDeg);
  return ConeFalloff(props, 10.0f, 1.0f);
}

/// Midpoint rule over theta of 2 pi f(theta) sin(theta) [cos(theta)].
double numericalSolidAngle(const ConeFalloff& f, bool projected) {
  const int n = 200000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double t = (i + 0.5) * (0.5 * Pi) / n;
    sum += f(float(std::cos(t))) * std::sin(t) * (projected ? std::cos(t) : 1.0);
  }
  return 2.0 * Pi * sum * (0.5 * Pi) / n;
}

}  // namespace

TEST(ConeFalloff, SolidAnglesMatchNumericalIntegrals) {
  for (auto [cutoff, beam] : {std::pair{10.0f, 10.0f}, {20.0f, 15.0f}, {45.0f, 0.0f}, {90.0f, 60.0f}, {30.0f, 29.99f}}) {
    ConeFalloff f = falloffOf(cutoff, beam);
    EXPECT_NEAR(f.solidAngle(), numericalSolidAngle(f, false), 2e-4 * f.solidAngle()) << cutoff << " " << beam;
    EXPECT_NEAR(f.projectedSolidAngle(), numericalSolidAngle(f, true), 2e-4 * f.projectedSolidAngle()) << cutoff << " " << beam;
  }
}

TEST(AngularArea, FalloffAroundTheNormalAndNothingBehind) {
  auto shape = lamp("<float name=\"cutoff_angle\" value=\"30\"/><float name=\"beam_width\" value=\"20\"/>");
  const Emitter& e = *shape->emitterRef();
  SurfaceInteraction si;
  si.n = Vec3f(0, 0, 1);
  auto at = [](float deg) { return Vec3f(std::sin(degToRad(deg)), 0.0f, std::cos(degToRad(deg))); };
  expectColorNear(e.eval(si, at(0.0f)), Radiance, 1e-5f);
  expectColorNear(e.eval(si, at(19.0f)), Radiance, 1e-5f);
  expectColorNear(e.eval(si, at(25.0f)), Radiance * 0.5f, 1e-4f);
  expectColorNear(e.eval(si, at(31.0f)), Color3f(0.0f), 0.0f);
  expectColorNear(e.eval(si, Vec3f(0, 0, -1)), Color3f(0.0f), 0.0f);
  // mitransient's defaults: a 10 degree cone without a soft edge.
  auto byDefault = lamp("");
  expectColorNear(byDefault->emitterRef()->eval(si, at(9.9f)), Radiance, 1e-5f);
  expectColorNear(byDefault->emitterRef()->eval(si, at(10.1f)), Color3f(0.0f), 0.0f);
}

TEST(AngularArea, NextEventEstimateIsRadianceTimesFalloffOverPdf) {
  auto shape = lamp("<float name=\"cutoff_angle\" value=\"40\"/><float name=\"beam_width\" value=\"10\"/>");
  const Emitter& e = *shape->emitterRef();
  const Point3f ref(0.7f, -0.4f, 2.0f);
  PCG32 rng(5, 1);
  int lit = 0;
  for (int i = 0; i < 200; ++i) {
    DirectionSample ds;
    Color3f value = e.sampleDirection(ref, {rng.nextFloat(), rng.nextFloat()}, ds);
    if (ds.pdf == 0.0f) continue;
    SurfaceInteraction si;
    si.n = ds.n;
    expectColorNear(value * ds.pdf, e.eval(si, -ds.d), 1e-4f);
    EXPECT_NEAR(e.pdfDirection(ref, ds), ds.pdf, 1e-4f * ds.pdf);
    lit += !value.isBlack();
  }
  EXPECT_GT(lit, 0);
}

TEST(AngularArea, EmittedRaysCarryThePowerOnAverage) {
  auto shape = lamp("<float name=\"cutoff_angle\" value=\"35\"/><float name=\"beam_width\" value=\"15\"/>");
  const Emitter& e = *shape->emitterRef();
  PCG32 rng(9, 1);
  const int n = 200000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    Ray ray;
    Color3f w = e.sampleRay({rng.nextFloat(), rng.nextFloat()}, {rng.nextFloat(), rng.nextFloat()}, ray);
    EXPECT_GE(ray.d.z, std::cos(degToRad(35.0f)) - 1e-5f);
    sum += w.g, sum2 += double(w.g) * w.g;
  }
  double mean = sum / n, stderror = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, e.power().g, 5.0 * stderror + 1e-6);
  // Le A times the projected solid angle: A = 4 for the 2x2 rectangle.
  EXPECT_NEAR(e.power().g, 2.0 * 4.0 * falloffOf(35.0f, 15.0f).projectedSolidAngle(), 1e-4);
}

TEST(AngularArea, WideOpenConeIsTheAreaLight) {
  auto wide = lamp("<float name=\"cutoff_angle\" value=\"90\"/><float name=\"beam_width\" value=\"90\"/>");
  auto area = lamp("", "area");
  expectColorNear(wide->emitterRef()->power(), area->emitterRef()->power(), 1e-4f * area->emitterRef()->power().b);
  SurfaceInteraction si;
  si.n = Vec3f(0, 0, 1);
  for (float deg : {0.0f, 45.0f, 89.0f}) {
    Vec3f w(std::sin(degToRad(deg)), 0.0f, std::cos(degToRad(deg)));
    expectColorNear(wide->emitterRef()->eval(si, w), area->emitterRef()->eval(si, w), 0.0f);
  }
}
