// transient_beams times a surface photon gathered at x along the photon's
// own last leg to x (surface_photon_map.h, lastLegDelay), not at the time it
// reached its own landing point up to a kernel radius away. A spot light
// shines only at a mirror, which throws its light obliquely onto a wall: the
// wall's light is all surface photons (one specular bounce, then the wall),
// and the time it reaches each wall point x is exactly |x - I| + |x - camera|
// with I the light's mirror image. A one-pixel camera with a narrow view sees
// a small patch of the wall; a large kernel radius (0.2) would spread the
// photons' own times over +-r sin(theta) = +-0.07 around that (7 bins of
// 0.01 either side). Timed along the last leg, nothing may arrive before the
// patch's earliest exact time (every deposit is the time of a real path, at
// least the shortest's), and nothing later than its latest plus the
// second-order residual r^2 / (2 leg) (0.006 here) and the surface time
// kernel's width (4 bins, beam_settings.h: deposits run [t, t + w]).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <femto/math/vector.h>
#include <femto/render/scene.h>

#include "media_test_util.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

const Point3f Camera(3.0f, 0.0f, 2.0f), Light(-2.0f, 0.0f, 1.0f);
// The mirror is the plane z = 3, so the light's image is at z = 5.
const Point3f Image(-2.0f, 0.0f, 5.0f), MirrorCentre(-1.2f, 0.0f, 3.0f);
constexpr float Fov = 0.5f, SurfaceRadius = 0.2f;
constexpr double Start = 8.5, BinWidth = 0.01;
constexpr int Bins = 100;

std::string mirrorScene() {
  return str(R"(<scene version="3.0.0">
  <integrator type="transient_beams"><integer name="photon_count" value="200000"/>
    <float name="surface_radius" value=")",
             SurfaceRadius, R"("/></integrator>
  <sensor type="perspective"><float name="fov" value=")",
             Fov, R"("/>
    <transform name="to_world"><lookat origin="3, 0, 2" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
    <film type="transient"><integer name="width" value="1"/><integer name="height" value="1"/>
      <integer name="temporal_bins" value=")",
             Bins, R"("/><float name="start_opl" value=")", Start, R"("/>
      <float name="bin_width_opl" value=")",
             BinWidth, R"("/><boolean name="write_frames" value="false"/><rfilter type="box"/></film>
  </sensor>
  <emitter type="spot"><transform name="to_world"><lookat origin="-2, 0, 1" target="-1.2, 0, 3"/></transform>
    <float name="cutoff_angle" value="20"/><float name="beam_width" value="20"/><float name="intensity" value="10"/></emitter>
  <shape type="rectangle"><transform name="to_world"><scale value="1.5"/><rotate x="1" angle="180"/>
      <translate x="-1.2" y="0" z="3"/></transform><bsdf type="conductor"/></shape>
  <shape type="rectangle"><bsdf type="diffuse"><float name="reflectance" value="0.8"/></bsdf></shape>
</scene>)");
}

/// Exact OPL of light reaching wall point x (z = 0) by the mirror, then the camera.
double exactOpl(const Point3f& x) { return double(distance(x, Image)) + double(distance(x, Camera)); }

}  // namespace

TEST(TransientBeamsSurfaceTiming, PhotonsAreTimedAlongTheirLastLegToTheGatherPoint) {
  // The patch the pixel sees lies within the cone of half-angle
  // atan(sqrt(2) tan(fov / 2)) around the view axis: its exact OPLs span
  // [lo, hi] (sampled densely over that cone, a superset of the pixel).
  const Vec3f axis = normalize(Point3f(0.0f) - Camera);
  const Vec3f u = normalize(cross(axis, Vec3f(0, 1, 0))), v = cross(u, axis);
  const double halfAngle = std::atan(std::sqrt(2.0) * std::tan(0.5 * double(Fov) * Pi / 180.0));
  double lo = Infinity, hi = -Infinity, nearestLeg = Infinity;
  for (int i = -40; i <= 40; ++i)
    for (int j = -40; j <= 40; ++j) {
      const double a = std::tan(halfAngle) * i / 40.0, b = std::tan(halfAngle) * j / 40.0;
      const Vec3f d = normalize(axis + u * float(a) + v * float(b));
      const Point3f x = Camera + d * (-Camera.z / d.z);
      lo = std::min(lo, exactOpl(x));
      hi = std::max(hi, exactOpl(x));
      // The last leg starts on the mirror: no nearer than its plane.
      nearestLeg = std::min(nearestLeg, double(MirrorCentre.z - x.z));
    }
  const double residual = double(SurfaceRadius) * SurfaceRadius / (2.0 * nearestLeg) + 4.0 * BinWidth;
  ASSERT_GT(lo, Start + 10 * BinWidth);
  ASSERT_LT(hi + residual, Start + (Bins - 10) * BinWidth);

  auto scene = loadSceneStrict(mirrorScene());
  Rendered r = render(scene, scratchDir("beams-surface-timing") / "mirror.exr", 5);
  ASSERT_EQ(r.bins, Bins);
  double total = 0.0, early = 0.0, late = 0.0;
  for (int k = 0; k < Bins; ++k) {
    const double value = r.volume[size_t(k) * 3 + 1];
    const double binStart = Start + k * BinWidth, binEnd = binStart + BinWidth;
    total += value;
    if (binEnd <= lo) early += value;
    if (binStart >= hi + residual) late += value;
  }
  ASSERT_GT(total, 0.0) << "no light reached the wall by the mirror";
  EXPECT_EQ(early, 0.0) << "energy before the earliest exact arrival " << lo;
  EXPECT_LT(late, 1e-3 * total) << "energy after the latest exact arrival " << hi << " + residual " << residual;
}
