// The time origin of transient films (issue 36, item 4): mitransient's
// transient_hdr_film counts each camera ray's OPL from its near-clip point,
// femto's transient film from the camera. Closed form: a camera at the origin
// facing a diffuse wall at z = D, lit by a point light at the camera, direct
// light only: a ray at angle theta to the axis hits the wall D / cos theta
// away, so its light arrives at 2 D / cos theta from the camera and
// (2 D - N) / cos theta from the near-clip point N / cos theta along it.
// Each pixel's light-weighted mean arrival must lie within the range of that
// form over the pixel (plus half a bin), under each film's convention; without
// observer time (the camera segment uncounted) both films give D / cos theta.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <femto/xml/loader.h>

#include "plugin_util.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr int Pixels = 9, Bins = 240;
constexpr double D = 4.0, NearClip = 1.5, BinWidth = 0.05, HalfFov = 30.0;

std::shared_ptr<Scene> wallScene(const std::string& film, bool observerTime) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="2"/>
    <boolean name="observer_time" value=")", observerTime ? "true" : "false", R"("/></integrator>
  <sensor type="perspective"><float name="fov" value=")", 2.0 * HalfFov, R"("/>
    <float name="near_clip" value=")", NearClip, R"("/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 1" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
    <film type=")", film, R"("><integer name="width" value=")", Pixels, R"("/><integer name="height" value=")", Pixels,
                             R"("/>
      <integer name="temporal_bins" value=")", Bins, R"("/><float name="start_opl" value="0"/>
      <float name="bin_width_opl" value=")", BinWidth, R"("/><rfilter type="box"/></film></sensor>
  <emitter type="point"><point name="position" x="0" y="0" z="0"/><float name="intensity" value="1"/></emitter>
  <shape type="rectangle"><transform name="to_world"><scale value="10"/><rotate y="1" angle="180"/>
    <translate z=")", D, R"("/></transform><bsdf type="diffuse"/></shape>
</scene>)"));
}

/// [min, max] of 1 / cos theta over pixel (i, j): sqrt(1 + x^2 + y^2) on the
/// plane z = 1, whose film spans [-tan, tan] in x and y.
std::pair<double, double> secantRange(int i, int j) {
  const double t = std::tan(HalfFov * Pi / 180.0);
  auto range = [&](int k) {
    double a = -t + 2.0 * t * k / Pixels, b = a + 2.0 * t / Pixels;
    double lo = a <= 0.0 && b >= 0.0 ? 0.0 : std::min(a * a, b * b);
    return std::make_pair(lo, std::max(a * a, b * b));
  };
  auto [xl, xh] = range(i);
  auto [yl, yh] = range(j);
  return {std::sqrt(1.0 + xl + yl), std::sqrt(1.0 + xh + yh)};
}

/// Every pixel's mean arrival (bin centres weighted by the green channel)
/// within [a, b] * its secant range, widened by half a bin.
void expectArrivals(const std::string& film, bool observerTime, double numerator) {
  SCOPED_TRACE(str(film, ", observer time ", observerTime ? "on" : "off"));
  auto dir = scratchDir("time-origin-" + film + (observerTime ? "-on" : "-off"));
  Rendered r = render(wallScene(film, observerTime), dir / "wall.exr", 5);
  ASSERT_EQ(r.bins, Bins);
  for (int row = 0; row < Pixels; ++row)
    for (int col = 0; col < Pixels; ++col) {
      double sum = 0.0, weighted = 0.0;
      for (int b = 0; b < Bins; ++b) {
        double v = r.volume[((size_t(row) * Pixels + col) * Bins + b) * 3 + 1];
        sum += v;
        weighted += v * (b + 0.5) * BinWidth;
      }
      ASSERT_GT(sum, 0.0) << "pixel " << col << ", " << row << " holds light";
      auto [lo, hi] = secantRange(col, row);
      double mean = weighted / sum;
      EXPECT_GE(mean, numerator * lo - 0.5 * BinWidth) << "pixel " << col << ", " << row;
      EXPECT_LE(mean, numerator * hi + 0.5 * BinWidth) << "pixel " << col << ", " << row;
    }
}

}  // namespace

TEST(TransientTimeOrigin, MitransientFilmCountsFromTheNearClipPoint) {
  expectArrivals("transient_hdr_film", true, 2.0 * D - NearClip);
}

TEST(TransientTimeOrigin, FemtoFilmCountsFromTheCamera) { expectArrivals("transient", true, 2.0 * D); }

TEST(TransientTimeOrigin, WithoutObserverTimeNeitherFilmShifts) {
  expectArrivals("transient_hdr_film", false, D);
  expectArrivals("transient", false, D);
}
