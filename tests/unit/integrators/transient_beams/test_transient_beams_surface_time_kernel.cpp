// The surface photons' causal time kernel (beam_settings.h, surface_time_width)
// against a closed form: a diffuse plane lit by a point light's pulse through
// an ideal mirror parallel to it, so that the light the camera sees in the
// film's window is all surface photons (one specular bounce, then the plane;
// direct light arrives before the window, max_depth 3 drops the rest). The
// mirror light reaching plane point p is I cos / |p - I|^2 from the light's
// image I, at OPL |p - I|.
//
// The estimator's expectation is known exactly: a camera hit x averages the
// plane's radiance over the disc of the pass's radius around it, each photon
// at p timed along its own last leg to x (through its mirror point q:
// |I - q| + |q - x|, surface_photon_map.h), and spreads it over [t, t + w_i]
// (the pass's width). Checked per fine bin, within 5 standard errors of the
// runs' mean:
//  * against that expectation with the kernel's widths (the kernel is what
//    it claims, schedule included);
//  * against the expectation without the time kernel (w = 0), plus the
//    derived bound: a one-sided box of width at most w_0 moves into or out of
//    a bin [a, b) at most the mass of [a - w_0, a) and of [b - w_0, b);
//  * nothing before the earliest arrival the disc allows (the rising edge:
//    causal), and the window's sum (the profile's integral) unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <femto/film/transient_film.h>
#include <femto/math/constants.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <transient_beams/beam_settings.h>

#include "media_test_util.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

constexpr double Intensity = 10.0, Reflectance = 0.8, MirrorHeight = 2.0;
const Point3f Light(0.0f, 0.0f, 1.0f);
const Point3f Image(0.0f, 0.0f, float(2.0 * MirrorHeight - 1.0));  // the light mirrored in z = MirrorHeight
const Point3f Camera(0.8f, 0.0f, 1.6f);
constexpr float Fov = 20.0f, SurfaceRadius = 0.15f;
constexpr int Resolution = 4, Passes = 4, Bins = 40;
constexpr double BinWidth = 0.01, Start = 4.60;

std::string scene(const std::string& width) {
  return str(R"(<scene version="3.0.0">
  <integrator type="transient_beams"><integer name="max_depth" value="3"/><integer name="passes" value=")",
             Passes, R"("/>
    <integer name="photon_count" value="20000"/><float name="surface_radius" value=")",
             SurfaceRadius, R"("/>)", width, R"(</integrator>
  <sensor type="perspective"><float name="fov" value=")",
             Fov, R"("/>
    <transform name="to_world"><lookat origin="0.8, 0, 1.6" target="0.3, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
    <film type="transient"><integer name="width" value=")",
             Resolution, R"("/><integer name="height" value=")", Resolution, R"("/>
      <integer name="temporal_bins" value=")",
             Bins, R"("/><float name="start_opl" value=")", Start, R"("/>
      <float name="bin_width_opl" value=")",
             BinWidth, R"("/><boolean name="write_frames" value="false"/><rfilter type="box"/></film>
  </sensor>
  <emitter type="spot"><transform name="to_world"><lookat origin="0, 0, 1" target="0, 0, 2"/></transform>
    <float name="beam_width" value="20"/><float name="cutoff_angle" value="21"/>
    <float name="intensity" value=")",
             Intensity, R"("/></emitter>
  <shape type="rectangle"><transform name="to_world"><scale value="20"/></transform>
    <bsdf type="diffuse"><float name="reflectance" value=")",
             Reflectance, R"("/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="20"/><rotate x="1" angle="180"/>
    <translate z=")",
             MirrorHeight, R"("/></transform><bsdf type="conductor"/></shape>
</scene>)");
}

/// Radiance of the plane at p from the mirrored light (ideal mirror, Lambertian plane).
double radiance(const Point3f& p) {
  const double d = distance(p, Image);
  return Reflectance * InvPi * Intensity * (double(Image.z) / d) / (d * d);
}

/// The expected image sum per bin of the estimator with the passes' radii
/// and time widths (`settings`, resolved), by quadrature: 8 x 8 sub-rays per
/// pixel through the sensor, a polar grid over each disc. `earliest`
/// receives the earliest OPL any deposit can start at.
/// Bins `bins` of `width` from `start` (the film's by default).
std::vector<double> expectedImageSums(const Scene& scene, const beams::BeamSettings& settings, double& earliest,
                                      double start = Start, double width = BinWidth, int bins = Bins) {
  std::vector<double> sums(size_t(bins), 0.0);
  earliest = Infinity;
  const int sub = 16, radial = 16, angular = 32;
  auto deposit = [&](double t, double w, double value) {
    if (w <= 0.0) {
      const int k = int(std::floor((t - start) / width));
      if (k >= 0 && k < bins) sums[size_t(k)] += value;
      return;
    }
    for (int k = std::max(0, int(std::floor((t - start) / width))); k < bins; ++k) {
      const double a = start + k * width, b = a + width;
      if (a >= t + w) break;
      sums[size_t(k)] += value * (std::min(b, t + w) - std::max(a, t)) / w;
    }
  };
  for (int pass = 0; pass < Passes; ++pass) {
    const double r = settings.surfaceRadiusOf(pass), w = settings.surfaceTimeWidthOf(pass);
    for (int py = 0; py < Resolution; ++py)
      for (int px = 0; px < Resolution; ++px)
        for (int j = 0; j < sub; ++j)
          for (int i = 0; i < sub; ++i) {
            Ray ray;
            scene.sensor().sampleRay(Point2f(px + (i + 0.5f) / sub, py + (j + 0.5f) / sub), Point2f(0.5f), ray);
            const Point3f x = ray.o + ray.d * (-ray.o.z / ray.d.z);
            const double camera = distance(x, ray.o);
            const double weight = 1.0 / (double(sub) * sub * Passes);
            // The disc average: rings of equal width, each point's area share.
            for (int a = 0; a < radial; ++a)
              for (int b = 0; b < angular; ++b) {
                const double rho = r * (a + 0.5) / radial, phi = 2.0 * Pi * (b + 0.5) / angular;
                const double area = rho * (r / radial) * (2.0 * Pi / angular) / (Pi * r * r);
                const Point3f p = x + Vec3f(float(rho * std::cos(phi)), float(rho * std::sin(phi)), 0.0f);
                // The photon's mirror point q on the way from the image to p.
                const double f = (double(Image.z) - MirrorHeight) / double(Image.z);
                const Point3f q = Image + (p - Image) * float(f);
                const double t = camera + distance(Image, q) + distance(q, x);
                earliest = std::min(earliest, t);
                deposit(t, w, weight * area * radiance(p));
              }
          }
  }
  return sums;
}

/// The derived bias bound of the causal box kernel of width w on bin [a, b)
/// (docs/design/photon-beams.md, "The surface time kernel"): the estimate is
/// the true arrival density f weighted by phi(tau) = |[tau, tau + w] & [a, b)| / w,
/// whose integral is b - a as that of the bin's indicator, so the bias is
/// the integral of (f - c)(phi - 1_[a, b)) for any c: at most
/// (sup f - inf f) over [a - w, b) times P, the positive part's integral of
/// phi - 1_[a, b): w / 2 for w <= b - a, else (b - a) - (b - a)^2 / (2 w).
/// `fine`: f as masses of bins of width `width` from `start`.
double timeKernelBound(const std::vector<double>& fine, double start, double width, double a, double b, double w) {
  double hi = 0.0, lo = Infinity;
  for (size_t j = 0; j < fine.size(); ++j) {
    const double u = start + double(j) * width;
    if (u + width <= a - w || u >= b) continue;
    hi = std::max(hi, fine[j] / width), lo = std::min(lo, fine[j] / width);
  }
  const double bin = b - a, positive = w <= bin ? 0.5 * w : bin - bin * bin / (2.0 * w);
  return hi > 0.0 ? positive * (hi - lo) : 0.0;
}

}  // namespace

TEST(TransientBeamsSurfaceTimeKernel, WidthIsFourBinsOrTheDiscsCrossingAtLeastABinAndShrinksWithTheRadiusAsOneVolume) {
  Properties props;
  beams::BeamSettings s = beams::BeamSettings::parse(props);
  EXPECT_LT(s.surfaceTimeWidth, 0.0f) << "absent: derived";
  TimeGrid grid;
  grid.bins = 100, grid.binWidth = 0.02, grid.start = 1.0;
  s.surfaceRadius = 0.1f;
  EXPECT_FLOAT_EQ(s.withSurfaceTimeWidthFor(grid).surfaceTimeWidth, float(beams::TimeBinFraction * 0.02));
  s.surfaceRadius = 0.03f;  // the disc's crossing, 0.06, is shorter than 4 bins
  EXPECT_FLOAT_EQ(s.withSurfaceTimeWidthFor(grid).surfaceTimeWidth, 0.06f);
  s.surfaceRadius = 0.009f;  // the disc's crossing, 0.018, is under a bin: no kernel
  EXPECT_FLOAT_EQ(s.withSurfaceTimeWidthFor(grid).surfaceTimeWidth, 0.0f);
  s.surfaceRadius = 0.03f;
  s = s.withSurfaceTimeWidthFor(grid);
  EXPECT_FLOAT_EQ(beams::BeamSettings::parse(props).withSurfaceTimeWidthFor(TimeGrid{}).surfaceTimeWidth, 0.0f)
      << "steady films have no time axis";
  s.surfaceRadius = 0.1f, s.alpha = 0.7f;
  double factor = 1.0;
  for (int pass = 0; pass < 6; ++pass) {
    // r^2 w shrinks by prod (i + alpha) / (i + 1), r^2 and w each by its root.
    EXPECT_NEAR(s.surfaceTimeWidthOf(pass), s.surfaceTimeWidth * std::sqrt(factor), 1e-7);
    EXPECT_NEAR(double(s.surfaceRadiusOf(pass)) * s.surfaceRadiusOf(pass) * s.surfaceTimeWidthOf(pass),
                0.01 * s.surfaceTimeWidth * factor, 1e-8);
    factor *= (pass + double(s.alpha)) / (pass + 1.0);
  }
  // Without the time kernel the 2D schedule: r^2 by the whole factor.
  s.surfaceTimeWidth = 0.0f;
  EXPECT_NEAR(s.surfaceRadiusOf(2), 0.1 * std::sqrt(0.7 * 1.7 / 2.0), 1e-7);
  EXPECT_EQ(s.surfaceTimeWidthOf(2), 0.0f);
}

TEST(TransientBeamsSurfaceTimeKernel, MirrorLitPlaneMatchesTheClosedFormWithinTheDerivedBound) {
  auto loaded = loadSceneStrict(scene(""));  // the width derived: 4 bins
  const auto& film = dynamic_cast<const TransientFilm&>(loaded->sensor().film());
  beams::BeamSettings settings = beams::BeamSettings::parse(Properties());  // alpha 0.9, as the scene's
  settings.passes = Passes, settings.surfaceRadius = SurfaceRadius;
  settings = settings.withSurfaceTimeWidthFor(film.timeGrid());
  ASSERT_NEAR(settings.surfaceTimeWidth, 4.0 * BinWidth, 1e-7);
  beams::BeamSettings instants = settings;
  instants.surfaceTimeWidth = 0.0f;
  double earliest = 0.0, earliestInstants = 0.0;
  const std::vector<double> kernel = expectedImageSums(*loaded, settings, earliest);
  const std::vector<double> exact = expectedImageSums(*loaded, instants, earliestInstants);
  // The arrival density without the time kernel, at a tenth of a bin.
  const double fineWidth = BinWidth / 10.0, fineStart = Start - 10 * BinWidth;
  const std::vector<double> fine =
      expectedImageSums(*loaded, instants, earliestInstants, fineStart, fineWidth, (Bins + 10) * 10);
  double total = 0.0;
  for (double v : exact) total += v;
  ASSERT_GT(earliestInstants, Start + 4 * BinWidth) << "the window must open before the first arrivals";
  double tail = 0.0;
  for (int k = Bins - 6; k < Bins; ++k) tail += kernel[size_t(k)];
  ASSERT_LT(tail, 1e-9 * total) << "the window must hold the whole profile and its kernel";

  const int runs = 16;
  const auto perRun = imageSumsPerRun(loaded, "beams-surface-time-kernel", runs);
  std::vector<Mean> est(Bins);
  Mean window;
  for (const auto& run : perRun) {
    double sum = 0.0;
    for (int k = 0; k < Bins; ++k) est[size_t(k)].add(run[size_t(k)]), sum += run[size_t(k)];
    window.add(sum);
  }
  const double w0 = settings.surfaceTimeWidth;
  double early = 0.0;
  for (int k = 0; k < Bins; ++k) {
    const double a = Start + k * BinWidth, b = a + BinWidth;
    const double se = est[size_t(k)].standardError();
    const double bound = timeKernelBound(fine, fineStart, fineWidth, a, b, w0);
    std::printf("bin %d: beams %.5g +- %.2g, expected %.5g, without the time kernel %.5g (bound %.2g)\n", k,
                est[size_t(k)].mean(), se, kernel[size_t(k)], exact[size_t(k)], bound);
    EXPECT_NEAR(est[size_t(k)].mean(), kernel[size_t(k)], 5.0 * se + 1e-3 * kernel[size_t(k)] + 1e-9) << "bin " << k;
    EXPECT_NEAR(est[size_t(k)].mean(), exact[size_t(k)], 5.0 * se + bound + 1e-9) << "bin " << k;
    if (b <= earliestInstants) early += est[size_t(k)].mean();
  }
  EXPECT_EQ(early, 0.0) << "energy before the earliest arrival " << earliestInstants;
  // The integral: the window holds the whole profile, the kernel only moves it in time.
  std::printf("window: beams %.6g +- %.2g, expected %.6g\n", window.mean(), window.standardError(), total);
  EXPECT_NEAR(window.mean(), total, 5.0 * window.standardError() + 1e-3 * total);
}
