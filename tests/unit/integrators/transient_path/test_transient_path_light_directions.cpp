// transient_path's light-directed next-event vertices (light_directions):
// one more estimator of the same transport, so with and without them the
// estimates agree within noise, also with time gating (which restricts the
// light-directed vertex's distances too) and with surfaces, an index-matched
// boundary and multiple scattering in between (randomised fog cubes: no closed
// form). The variance they remove is tested in
// test_transient_path_worst_cells.cpp; the direction density itself in
// tests/unit/transport/test_point_directions.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include <femto/math/pcg32.h>

#include "media_test_util.h"
#include "plugin_util.h"
#include "render_test_util.h"
#include "transient_test_util.h"
#include "window_estimate.h"

using namespace femto;
using namespace femto::test;

namespace {

struct FogCube {
  float sigmaT, albedo;
  Point3f light;
  float floorY = -0.95f;  // below -1: outside the cube, a vacuum gap between the two
};

/// A fog cube (index-matched) holding a point light and a diffuse floor, seen
/// from outside: camera paths cross the boundary, scatter on the floor and in
/// the fog. With the floor below the cube, rays from the floor cross a vacuum
/// gap and the boundary before the fog (light-directed vertices follow them).
std::string integratorXml(int maxDepth, bool lightDirections, bool gating) {
  return str(R"(<integrator type="transient_path"><integer name="max_depth" value=")", maxDepth,
             R"("/><boolean name="light_directions" value=")", lightDirections ? "true" : "false",
             R"("/><boolean name="time_gating" value=")", gating ? "true" : "false", R"("/></integrator>)");
}

std::shared_ptr<Scene> fogCube(const FogCube& c, bool lightDirections, bool gating) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  )",
                             integratorXml(6, lightDirections, gating), R"(
  <medium id="fog" type="homogeneous"><rgb name="sigma_t" value=")",
                             c.sigmaT, R"("/>
    <rgb name="albedo" value=")",
                             c.albedo, R"("/></medium>
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.95"/><rotate x="1" angle="-90"/><translate y=")",
                             c.floorY, R"("/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.7"/></bsdf>
  </shape>
  <emitter type="point"><point name="position" x=")",
                             c.light.x, R"(" y=")", c.light.y, R"(" z=")", c.light.z,
                             R"("/><float name="intensity" value="3"/></emitter>
  <sensor type="perspective"><transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform></sensor>
</scene>)"));
}

Ray cameraRay(PCG32& rng) {
  Point3f target(rng.nextFloat() * 1.6f - 0.8f, rng.nextFloat() * 1.6f - 0.8f, 0.0f);
  return Ray(Point3f(0.0f, 0.0f, 4.0f), normalize(target - Point3f(0.0f, 0.0f, 4.0f)));
}

/// Paths of up to 3 segments from a camera inside an unbounded homogeneous
/// medium (`medium`: its parameters as XML), with `shapes` and a point light
/// of intensity 2 at `light` ("x y z" attributes).
std::shared_ptr<Scene> cameraInMedium(bool lightDirections, const std::string& medium, const std::string& shapes,
                                      const std::string& light) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="3"/>
    <boolean name="light_directions" value=")",
                             lightDirections ? "true" : "false", R"("/></integrator>
  <medium id="m" type="homogeneous">)",
                             medium, R"(</medium>
  <sensor type="perspective"><ref id="m"/></sensor>)",
                             shapes, R"(
  <emitter type="point"><point name="position" )",
                             light, R"(/><float name="intensity" value="2"/></emitter>
</scene>)"));
}

void expectBinsAgree(const WindowEstimate& a, const WindowEstimate& b) {
  for (size_t k = 0; k < a.bins.size(); ++k) {
    double se = std::hypot(a.bins[k].standardError(), b.bins[k].standardError());
    EXPECT_NEAR(a.bins[k].mean(), b.bins[k].mean(), 5.0 * se)
        << "bin " << k << ": " << a.bins[k].mean() << " +- " << a.bins[k].standardError() << " vs " << b.bins[k].mean()
        << " +- " << b.bins[k].standardError();
  }
  double se = std::hypot(a.total.standardError(), b.total.standardError());
  EXPECT_NEAR(a.total.mean(), b.total.mean(), 5.0 * se);
}

/// Heights of the light: [low, low + span).
struct HeightRange {
  float low, span;
};
struct SeedPair {
  uint64_t with, without;
};

/// `count` fog cubes drawn from `scenes` (the light at a height in `heights`,
/// the floor at `floorY`), rendered with and without light-directed vertices
/// over OPL 3 to 7 (first arrivals to late multiple scattering): the bins agree.
void expectAgreeWithoutThem(PCG32& scenes, int count, HeightRange heights, float floorY, SeedPair seeds) {
  const TimeGrid grid{3.0, 0.5, 8};
  for (int k = 0; k < count; ++k) {
    FogCube c{
        0.3f + 1.2f * scenes.nextFloat(), 0.5f + 0.45f * scenes.nextFloat(),
        Point3f(scenes.nextFloat() - 0.5f, heights.low + heights.span * scenes.nextFloat(), scenes.nextFloat() - 0.5f),
        floorY};
    SCOPED_TRACE(str("scene ", k, ": sigma_t ", c.sigmaT, " albedo ", c.albedo, " light ", c.light));
    const int n = 20000;
    WindowEstimate with = estimateWindow(*fogCube(c, true, false), grid, n, seeds.with + k, cameraRay);
    WindowEstimate without = estimateWindow(*fogCube(c, false, false), grid, n, seeds.without + k, cameraRay);
    ASSERT_GT(without.total.mean(), 0.0) << "the window holds light: the test compares something";
    expectBinsAgree(with, without);
  }
}

}  // namespace

TEST(TransientPathLightDirections, AgreeWithoutThemOnRandomisedFogCubes) {
  PCG32 scenes(15, 7);
  expectAgreeWithoutThem(scenes, 3, {0.2f, 0.6f}, -0.95f, {300, 400});
}

TEST(TransientPathLightDirections, AgreeWithoutThemAcrossAVacuumGap) {
  PCG32 scenes(17, 7);
  expectAgreeWithoutThem(scenes, 2, {-0.8f, 0.3f}, -1.1f, {900, 950});
}

TEST(TransientPathLightDirections, AgreeWithoutThemWithTheLightJustAboveTheFloor) {
  // The floor right under the light is the hot spot (irradiance ~ 1/r^2) that
  // light-directed rays reach past the light (transient_path's
  // lightDirectedSurface): its next-event estimates are shared between them
  // and the paths' own directions, so weights that do not sum to one show
  // here first (the floor's estimates counted twice: 5 to 7 standard errors).
  PCG32 scenes(18, 7);
  expectAgreeWithoutThem(scenes, 2, {-0.85f, 0.1f}, -0.95f, {1000, 1050});
}

TEST(TransientPathLightDirections, AgreeWithoutThemThroughAnAbsorbingMedium) {
  // The camera looks up at a ceiling; a point light sits just above the
  // floor, in a medium that only absorbs. Light reaches the ceiling directly
  // and from the floor's hot spot under the light, which the ceiling's
  // light-directed rays reach past the light. Free flights cross the 2 units
  // to the floor with probability T ~ 0.1, so the paths' own directions count
  // with density p_bsdf T there: weights that leave T out do not sum to one.
  auto scene = [](bool lightDirections) {
    return cameraInMedium(lightDirections, R"(<float name="sigma_t" value="1.2"/><float name="albedo" value="0"/>)",
                          R"(
  <shape type="rectangle">
    <transform name="to_world"><scale value="2"/><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.8"/></bsdf>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="2"/><rotate x="1" angle="90"/><translate y="1"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.8"/></bsdf>
  </shape>)",
                          R"(x="0.1" y="-0.9" z="0")");
  };
  auto rays = [](PCG32& rng) {
    Vec3f target((rng.nextFloat() - 0.5f) * 0.8f, 1.0f, (rng.nextFloat() - 0.5f) * 0.8f);
    return Ray(Point3f(0.0f), normalize(target));
  };
  const TimeGrid grid{1.0, 1.0, 4};  // where the light is: later bins hold a few samples or none
  const int n = 100000;
  WindowEstimate with = estimateWindow(*scene(true), grid, n, 1100, rays);
  WindowEstimate without = estimateWindow(*scene(false), grid, n, 1200, rays);
  ASSERT_GT(without.total.mean(), 0.0) << "light reaches the ceiling: the test compares something";
  expectBinsAgree(with, without);
}

TEST(TransientPathLightDirections, GatedAgreeWithUngatedWithoutThem) {
  PCG32 scenes(16, 7);
  for (int k = 0; k < 3; ++k) {
    FogCube c{0.3f + 1.2f * scenes.nextFloat(), 0.5f + 0.45f * scenes.nextFloat(),
              Point3f(scenes.nextFloat() - 0.5f, 0.2f + 0.6f * scenes.nextFloat(), scenes.nextFloat() - 0.5f)};
    const TimeGrid grid{5.0 + 2.0 * scenes.nextFloat(), 0.25, 4};  // a late window
    SCOPED_TRACE(str("scene ", k, ": sigma_t ", c.sigmaT, " albedo ", c.albedo, " light ", c.light, " window from ",
                     grid.start));
    const int n = 20000;
    WindowEstimate gated = estimateWindow(*fogCube(c, true, true), grid, n, 500 + k, cameraRay);
    WindowEstimate plain = estimateWindow(*fogCube(c, false, false), grid, n, 600 + k, cameraRay);
    ASSERT_GT(plain.total.mean(), 0.0) << "the window holds light: the test compares something";
    expectBinsAgree(gated, plain);
  }
}

TEST(TransientPathLightDirections, DoubleScatteringBesideTheLightAgreesWithoutThem) {
  // Where they matter most: unbounded fog, a light beside the view, double
  // scattering only; the light-directed vertices carry much of the second
  // bounce here, so weights that do not sum to one show.
  auto scene = [](bool lightDirections) {
    return cameraInMedium(lightDirections, R"(<float name="sigma_t" value="0.8"/><float name="albedo" value="0.75"/>)",
                          "", R"(x="0.45" y="0.02" z="1")");
  };
  auto rays = [](PCG32& rng) {
    Vec3f target((rng.nextFloat() - 0.5f) * 0.4f, (rng.nextFloat() - 0.5f) * 0.4f, 1.0f);
    return Ray(Point3f(0.0f), normalize(target));
  };
  const TimeGrid grid{1.0, 0.5, 8};
  const int n = 200000;
  WindowEstimate with = estimateWindow(*scene(true), grid, n, 700, rays);
  WindowEstimate without = estimateWindow(*scene(false), grid, n, 800, rays);
  expectBinsAgree(with, without);
}

TEST(TransientPathLightDirections, DoubleScatteringInHeterogeneousFogAgreesWithoutThem) {
  // The same in a grid fog around the camera (a cube of it, index-matched):
  // the light-directed vertex takes the first heterogeneous segment of its
  // ray (ratio tracking's transmittance to it) and shares its distances with
  // the path's own equiangular vertex by the direction densities alone (free
  // flights take none of them there). Either weight left at 1 counts that
  // share twice (+4 % over the window). Gated, in a late window, against
  // the same without gating: the light-directed and equiangular vertices
  // sample the same window-restricted distances. (Not against the paths
  // without light-directed vertices there: their heavy tail, the fireflies
  // these vertices remove, read 3.9 standard errors low on one seed pair
  // where 4 x 400000 paths agree within 0.2 %.)
  auto dir = scratchDir("light-directions-grid");
  writeDensityGrid(dir / "density.vol", 6, 2.0f);
  auto scene = [&](bool lightDirections, bool gating) {
    return loadSceneStrict(str(R"(<scene version="3.0.0">
  )",
                               integratorXml(3, lightDirections, gating), R"(
  <medium id="m" type="heterogeneous"><volume name="sigma_t" type="gridvolume"><string name="filename" value=")",
                               (dir / "density.vol").string(), R"("/></volume>
    <float name="scale" value="0.7"/><rgb name="albedo" value="0.8, 0.75, 0.7"/></medium>
  <shape type="cube"><transform name="to_world"><scale value="2"/></transform><ref name="interior" id="m"/></shape>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x="0.45" y="0.02" z="1"/><float name="intensity" value="2"/></emitter>
</scene>)"));
  };
  auto rays = [](PCG32& rng) {
    Vec3f target((rng.nextFloat() - 0.5f) * 0.4f, (rng.nextFloat() - 0.5f) * 0.4f, 1.0f);
    return Ray(Point3f(0.0f), normalize(target));
  };
  // Scene a against scene b (the reference) over `grid`, 200000 paths each.
  auto expectAgree = [&](const Scene& a, const Scene& b, const TimeGrid& grid, uint64_t seed) {
    WindowEstimate ea = estimateWindow(a, grid, 200000, seed, rays);
    WindowEstimate eb = estimateWindow(b, grid, 200000, seed + 100, rays);
    ASSERT_GT(eb.total.mean(), 0.0) << "the window holds light: the test compares something";
    expectBinsAgree(ea, eb);
  };
  {
    SCOPED_TRACE("with and without them");
    expectAgree(*scene(true, false), *scene(false, false), TimeGrid{1.0, 0.5, 8}, 1300);
  }
  {
    SCOPED_TRACE("gated and not, with them");
    expectAgree(*scene(true, true), *scene(true, false), TimeGrid{2.5, 0.25, 4}, 1500);
  }
  std::filesystem::remove_all(dir);
}
