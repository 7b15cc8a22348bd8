// The derived surface photon radius (surface_radius_rule.h): the density
// bound is the k-nearest-photon distance (photons on the camera's side only),
// sqrt(k / (pi rho)) for photons of density rho on a plane; the pixel bound
// is PixelFootprints times what one pixel spans on the surface, exactly
// 2 D tan(fov / 2) / width on a plane facing the camera at distance D; and
// with no smooth surface in view (or no photons) the rule declines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <femto/math/pcg32.h>
#include <transient_beams/surface_radius_rule.h>

#include "media_test_util.h"

namespace femto::beams {
namespace {

/// A 20 x 20 diffuse (or mirror) wall at z = 0 facing +z, seen head-on from z = 5.
std::shared_ptr<Scene> wallSeenHeadOn(const char* bsdf = "diffuse") {
  return test::loadSceneStrict(str(R"(<scene version="3.0.0">
    <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform><bsdf type=")",
                                   bsdf, R"("/></shape>
    <sensor type="perspective"><float name="fov" value="40"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="64"/><integer name="height" value="64"/></film></sensor>
    <emitter type="point"><point name="position" x="0" y="0" z="3"/></emitter></scene>)"));
}

TEST(SurfaceRadiusRule, NearestPhotonRadiusMatchesTheDensity) {
  // 40000 photons on [-1, 1]^2 facing +z (rho = 10000): the 64th nearest
  // lies about sqrt(64 / (pi rho)) = 0.0451 away; as many facing -z at the
  // same places are not on the probes' side and change nothing.
  PCG32 rng(9, 4);
  std::vector<SurfacePhoton> photons;
  for (int i = 0; i < 40000; ++i) {
    SurfacePhoton ph;
    ph.p = Point3f(2.0f * rng.nextFloat() - 1.0f, 2.0f * rng.nextFloat() - 1.0f, 0.0f);
    ph.n = Normal3f(0.0f, 0.0f, 1.0f);
    photons.push_back(ph);
  }
  std::vector<SurfaceProbe> probes;
  for (int i = 0; i < 101; ++i)
    probes.push_back({Point3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0.0f), Normal3f(0.0f, 0.0f, 1.0f)});
  std::vector<double> one = nearestPhotonRadii(photons, probes, SurfacePhotonsPerGather, 1.0);
  const size_t n = photons.size();
  for (size_t i = 0; i < n; ++i) {
    SurfacePhoton back = photons[i];
    back.n = Normal3f(0.0f, 0.0f, -1.0f);
    photons.push_back(back);
  }
  std::vector<double> both = nearestPhotonRadii(photons, probes, SurfacePhotonsPerGather, 1.0);
  EXPECT_EQ(one, both);
  std::nth_element(one.begin(), one.begin() + 50, one.end());
  EXPECT_NEAR(one[50], std::sqrt(SurfacePhotonsPerGather / (Pi * 10000.0)), 0.1 * 0.0451);
  // Fewer photons than k within the bound: the bound.
  EXPECT_EQ(nearestPhotonRadii(photons, probes, SurfacePhotonsPerGather, 0.01)[0], 0.01);
}

TEST(SurfaceRadiusRule, PixelBoundIsTwoPixelFootprints) {
  auto scene = wallSeenHeadOn();
  std::vector<SurfacePhoton> photons(1);
  photons[0].n = Normal3f(0.0f, 0.0f, 1.0f);
  const DerivedSurfaceRadius d = deriveSurfaceRadius(*scene, photons, 1.0);
  const double footprint = 2.0 * 5.0 * std::tan(20.0 * Pi / 180.0) / 64.0;
  EXPECT_NEAR(d.pixels, PixelFootprints * footprint, 1e-4);
  EXPECT_EQ(d.density, 1.0);  // one photon: the search's bound
  EXPECT_EQ(d.radius, d.pixels);
}

TEST(SurfaceRadiusRule, DeclinesWithoutPhotonsOrSmoothSurfaces) {
  std::vector<SurfacePhoton> photons(1);
  EXPECT_EQ(deriveSurfaceRadius(*wallSeenHeadOn(), {}, 1.0).radius, 0.0);
  EXPECT_TRUE(surfaceProbes(*wallSeenHeadOn("conductor")).empty());
  EXPECT_EQ(deriveSurfaceRadius(*wallSeenHeadOn("conductor"), photons, 1.0).radius, 0.0);
}

}  // namespace
}  // namespace femto::beams
