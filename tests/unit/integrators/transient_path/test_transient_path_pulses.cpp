// Emitter pulses end to end with transient_path and the transient film: the
// same camera samples rendered with a Dirac and with a pulse. A gaussian
// pulse equals the Dirac render through a gaussian time filter of the same
// width (the convolution); a box pulse lies within exact bounds of the Dirac
// render on a 16x finer time axis convolved with the box; continuous emission
// is the running integral of the Dirac frames and its last frame is the
// steady image. Every emitter kind that transient_path finds (point light by
// next-event estimation, area light hit and sampled, environment) carries the pulse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/render/scene.h>
#include <femto/film/transient_film.h>
#include <femto/film/transient_tile.h>
#include <femto/xml/loader.h>

#include "continuous_pulse_check.h"
#include "media_test_util.h"
#include "plugin_util.h"
#include "transient_film_test_util.h"
#include "transient_test_util.h"

using namespace femto;

namespace {

constexpr int Size = 8;

/// A diffuse floor and back wall lit by a point light, a spherical area light
/// and a dim constant environment, each emitting with `pulse` (XML
/// parameters). max_depth 4 keeps every path's OPL below ~60, inside every
/// window below, so no render stops a path early and the same seed gives the
/// same paths whatever the film's time axis (time_splitting off: its time
/// profile, and so its paths, depend on the axis and the pulse).
std::string scene(const std::string& pulse, const std::string& film, int spp = 4) {
  return str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="4"/>
    <boolean name="time_splitting" value="false"/></integrator>
  <shape type="rectangle">
    <transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.3, 0.5, 0.7"/></bsdf>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="3"/><translate z="-2"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.6"/></bsdf>
  </shape>
  <shape type="sphere">
    <point name="center" x="-0.6" y="0.5" z="-0.5"/><float name="radius" value="0.3"/>
    <emitter type="area"><rgb name="radiance" value="4"/>)", pulse, R"(</emitter>
  </shape>
  <emitter type="point"><point name="position" x="0.8" y="1.2" z="0.5"/><rgb name="intensity" value="3, 2, 1"/>)",
             pulse, R"(</emitter>
  <emitter type="constant"><rgb name="radiance" value="0.05"/>)", pulse, R"(</emitter>
  <sensor type="perspective">
    <float name="fov" value="60"/>
    <transform name="to_world"><lookat origin="0, 0.5, 4" target="0, -0.3, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value=")",
             spp, R"("/></sampler>
    )", film, R"(
  </sensor>
</scene>)");
}

std::string transientFilm(double start, double binWidth, int bins, const std::string& extra = "") {
  return str(R"(<film type="transient"><integer name="width" value=")", Size, R"("/><integer name="height" value=")",
             Size, R"("/><integer name="temporal_bins" value=")", bins, R"("/><float name="start_opl" value=")", start,
             R"("/><float name="bin_width_opl" value=")", binWidth, R"("/><boolean name="write_frames" value="false"/>)",
             extra, "</film>");
}

std::string pulseXml(const std::string& type, const std::string& params) {
  return str(R"(<string name="pulse" value=")", type, R"("/>)", params);
}

/// A rendered transient film: volume (h, w, bins, 3) and the steady/before/after images.
struct Render {
  std::vector<float> volume;
  int bins = 0;
  Bitmap steady, before, after;
  float v(int x, int y, int b, int c) const { return volume[((size_t(y) * Size + x) * bins + b) * 3 + c]; }
};

Render render(const std::string& xml, const std::string& name, int threads = 0) {
  auto dir = test::scratchDir("pulses-" + name);
  auto loaded = test::loadSceneStrict(xml);
  RenderOptions options;
  options.output = dir / "out.exr";
  options.seed = 3;
  options.threads = threads;
  options.progress = false;
  RenderStats stats = loaded->integrator().render(*loaded, options);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  Render r;
  int h = 0, w = 0;
  r.volume = test::readVolume(dir / "out.npy", h, w, r.bins);
  r.steady = readImage(dir / "out.exr");
  r.before = readImage(dir / "out_before.exr");
  r.after = readImage(dir / "out_after.exr");
  std::filesystem::remove_all(dir);
  return r;
}

/// Float-precision comparison of two sums of the same contributions.
void expectClose(double a, double b, double scale, const std::string& what) {
  EXPECT_NEAR(a, b, 1e-5 * scale + 1e-7) << what;
}

double imageScale(const Render& r) {
  double m = 0.0;
  for (int y = 0; y < Size; ++y)
    for (int x = 0; x < Size; ++x)
      for (int c = 0; c < 3; ++c) m = std::max(m, double(r.steady.pixel(x, y)[c]));
  return m;
}

}  // namespace

TEST(TransientPathPulses, GaussianPulseIsTheDiracRenderConvolvedWithTheGaussian) {
  // Pulse: sigma 2.5, centred at OPL 3. Reference: Dirac emitters through a
  // gaussian time filter of 2.5 bins (bin width 1) on a window shifted by -3.
  Render pulsed = render(scene(pulseXml("gaussian", R"(<float name="pulse_sigma" value="2.5"/><float name="pulse_offset" value="3"/>)"),
                               transientFilm(-8.0, 1.0, 128)),
                         "gaussian");
  Render dirac = render(scene("", transientFilm(-11.0, 1.0, 128,
                                                R"(<string name="time_filter" value="gaussian"/><float name="time_filter_width" value="2.5"/>)")),
                        "gaussian-ref");
  const double scale = imageScale(dirac);
  ASSERT_GT(scale, 0.0);
  double arrived = 0.0;
  for (int y = 0; y < Size; ++y)
    for (int x = 0; x < Size; ++x)
      for (int c = 0; c < 3; ++c) {
        expectClose(pulsed.steady.pixel(x, y)[c], dirac.steady.pixel(x, y)[c], scale, "steady: pulses are normalised");
        expectClose(pulsed.before.pixel(x, y)[c], dirac.before.pixel(x, y)[c], scale, "before");
        for (int b = 0; b < 128; ++b) {
          expectClose(pulsed.v(x, y, b, c), dirac.v(x, y, b, c), scale, str("pixel ", x, ",", y, " bin ", b));
          arrived += pulsed.v(x, y, b, c);
        }
      }
  EXPECT_GT(arrived, 0.0);
}

TEST(TransientPathPulses, BoxPulseLiesWithinTheBoundsOfTheFineDiracRenderConvolvedWithTheBox) {
  // Box of width 4 starting at OPL 2. The Dirac render on a 16x finer axis
  // knows each contribution's OPL to 1/16; a box pulse's share of a coarse bin
  // is linear in the OPL between fine-bin edges (width, offset and coarse
  // edges are multiples of 1/16), so it lies between its values at the two
  // edges: summed over the fine bins, exact bounds on every coarse bin.
  const double w = 4.0, o = 2.0, start = -8.0;
  const int bins = 96, refine = 16;
  Render pulsed = render(scene(pulseXml("box", R"(<float name="pulse_width" value="4"/><float name="pulse_offset" value="2"/>)"),
                               transientFilm(start, 1.0, bins)),
                         "box");
  Render fine = render(scene("", transientFilm(start, 1.0 / refine, bins * refine)), "box-ref");
  const double scale = imageScale(fine);
  auto share = [&](int bin, double t) {  // share of coarse bin `bin` for a contribution at OPL t
    double lo = start + bin, hi = lo + 1.0;
    return std::max(0.0, std::min(hi, t + o + w) - std::max(lo, t + o)) / w;
  };
  int tight = 0;
  for (int y = 0; y < Size; ++y)
    for (int x = 0; x < Size; ++x)
      for (int c = 0; c < 3; ++c) {
        expectClose(pulsed.steady.pixel(x, y)[c], fine.steady.pixel(x, y)[c], scale, "steady");
        for (int b = 0; b < bins; ++b) {
          double lower = 0.0, upper = 0.0;
          for (int j = 0; j < bins * refine; ++j) {
            double f = fine.v(x, y, j, c);
            if (f == 0.0) continue;
            double s0 = share(b, start + double(j) / refine), s1 = share(b, start + double(j + 1) / refine);
            lower += f * std::min(s0, s1), upper += f * std::max(s0, s1);
          }
          double v = pulsed.v(x, y, b, c);
          EXPECT_GE(v, lower - 1e-5 * scale - 1e-7) << "pixel " << x << "," << y << " bin " << b;
          EXPECT_LE(v, upper + 1e-5 * scale + 1e-7) << "pixel " << x << "," << y << " bin " << b;
          tight += upper - lower < 0.1 * std::max(upper, 1e-3 * scale);
        }
      }
  EXPECT_GT(tight, Size * Size * 3 * bins / 2) << "the bounds must be narrow enough to mean something";
}

TEST(TransientPathPulses, ContinuousEmissionIsTheRunningIntegralAndEndsAtTheSteadyImage) {
  // Same axis for both. Bin i of the continuous render averages the running
  // integral over the bin, so it lies between the Dirac sums up to bin i-1
  // and up to bin i (plus what arrived before the window); with everything
  // arrived well before the window's end, the last frame is the steady image.
  const int bins = 96;
  Render step = render(scene(pulseXml("continuous", ""), transientFilm(-8.0, 1.0, bins)), "continuous");
  Render dirac = render(scene("", transientFilm(-8.0, 1.0, bins)), "continuous-ref");
  const double scale = imageScale(dirac);
  for (int y = 0; y < Size; ++y)
    for (int x = 0; x < Size; ++x)
      for (int c = 0; c < 3; ++c) {
        const double steady = step.steady.pixel(x, y)[c];
        expectClose(steady, dirac.steady.pixel(x, y)[c], scale, "steady");
        EXPECT_EQ(dirac.after.pixel(x, y)[c], 0.0f) << "all light arrives inside the window";
        expectClose(step.after.pixel(x, y)[c], 0.0, scale, "after: nothing still to arrive");
        expectClose(step.before.pixel(x, y)[c], dirac.before.pixel(x, y)[c], scale, "before: the level at the start");
        expectClose(step.v(x, y, bins - 1, c), steady, scale, "the last frame is the steady image");
      }
  EXPECT_TRUE(test::isRunningIntegralOf(step.volume, dirac.volume, dirac.before, Size, Size, bins, scale));
}

TEST(TransientPathPulses, PulsedRendersAreIndependentOfTheThreadCount) {
  const std::string xml = scene(pulseXml("gaussian", R"(<float name="pulse_fwhm" value="3"/>)"), transientFilm(-8.0, 1.0, 64));
  const std::string xml2 = scene(pulseXml("continuous", ""), transientFilm(-8.0, 1.0, 64));
  EXPECT_EQ(render(xml, "threads-1", 1).volume, render(xml, "threads-2", 2).volume);
  EXPECT_EQ(render(xml2, "step-threads-1", 1).volume, render(xml2, "step-threads-2", 2).volume);
}

TEST(TransientPathPulses, EachContributionCarriesItsEmittersPulse) {
  // Point light (next-event estimation only) with a box pulse, area light
  // (hit and sampled) with a gaussian one: the recorder sees each pulse.
  auto loaded = test::loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="2"/></integrator>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/></transform>
    <bsdf type="diffuse"/></shape>
  <shape type="sphere"><point name="center" x="0" y="0" z="1"/><float name="radius" value="0.2"/>
    <emitter type="area"><rgb name="radiance" value="1"/><string name="pulse" value="gaussian"/>
      <float name="pulse_sigma" value="0.5"/></emitter></shape>
  <emitter type="point"><point name="position" x="1" y="0" z="1"/><rgb name="intensity" value="1"/>
    <string name="pulse" value="box"/><float name="pulse_width" value="2"/></emitter>
</scene>)"));
  const auto& integrator = test::transientIntegrator(*loaded);
  auto sampler = test::seededSampler(5);
  int boxes = 0, gaussians = 0, hitsOfTheSphere = 0;
  for (int i = 0; i < 200; ++i) {
    test::CollectingRecorder recorder;
    // Half the rays aim at the sphere (emission found), half at the floor (next-event estimation).
    Vec3f d = i % 2 ? normalize(Point3f(0, 0, 1) - Point3f(0, -0.5f, 4)) : normalize(Point3f(0.3f, 0.2f, 0) - Point3f(0, -0.5f, 4));
    integrator.sample(*loaded, Ray(Point3f(0, -0.5f, 4), d), *sampler, recorder);
    for (const EmissionPulse& p : recorder.pulses) {
      boxes += p == EmissionPulse::box(2.0);
      gaussians += p == EmissionPulse::gaussian(0.5);
    }
    hitsOfTheSphere += i % 2 && !recorder.pulses.empty() && recorder.pulses[0] == EmissionPulse::gaussian(0.5);
  }
  // Next-event estimation picks either emitter with probability ~1/2 on the
  // ~100 floor rays: ~50 each (standard deviation 5), so 20 is 6 sigma away.
  EXPECT_GT(boxes, 20);
  EXPECT_GT(gaussians, 20);
  EXPECT_EQ(hitsOfTheSphere, 100) << "camera rays at the sphere record its emission with its pulse";
}

TEST(TransientPathPulses, HorizonAllowsForTheEarliestPulseAndGaussianNeedsTheBoxFilter) {
  auto loaded = test::loadSceneStrict(
      scene(pulseXml("gaussian", R"(<float name="pulse_sigma" value="0.5"/><float name="pulse_offset" value="1"/>)"),
            transientFilm(0.0, 1.0, 10)));
  auto& film = dynamic_cast<const TransientFilm&>(loaded->sensor().film());
  // The gaussian reaches 4 sigma = 2 before its centre at 1: light from paths up to OPL 10 + 1 may arrive.
  EXPECT_DOUBLE_EQ(pulsedHorizon(film.timeDeposit(), *loaded), 10.0 + 1.0);
  auto tent = test::loadSceneStrict(scene(pulseXml("gaussian", R"(<float name="pulse_sigma" value="0.5"/>)"),
                                          transientFilm(0.0, 1.0, 10, R"(<string name="time_filter" value="tent"/>)")));
  RenderOptions options;
  options.progress = false;
  options.output = test::scratchDir("pulses-tent") / "out.exr";
  std::string m = test::errorMessageOf([&] { tent->integrator().render(*tent, options); });
  EXPECT_NE(m.find("time_filter \"box\""), std::string::npos) << m;
}
