// transient_beams in a medium: single scattering from a point pulse seen by
// one camera ray against its closed form (single_scattering_model.h, shared
// with transient_path's test). The beam estimate blurs the in-scattered
// radiance over the kernel radius, so it converges as the radius shrinks:
// at a large radius the bias shows, at a small one the estimate agrees within
// its error bars (estimated from independent passes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <transient_beams/beam_pass.h>

#include "media_test_util.h"
#include "single_scattering_model.h"
#include "transient_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

/// Deposits each contribution into fixed OPL bins exactly (intervals spread uniformly).
class HistogramRecorder final : public RadianceRecorder {
 public:
  HistogramRecorder(double start, double width, int bins) : start_(start), width_(width), bins(size_t(bins), 0.0) {}
  void add(double opl, const Color3f& value) override { addInterval(opl, opl, value); }
  void addInterval(double opl0, double opl1, const Color3f& value) override {
    total += value.g;
    const double length = opl1 - opl0;
    for (size_t b = 0; b < bins.size(); ++b) {
      double lo = start_ + width_ * double(b), hi = lo + width_;
      double share = length > 0.0 ? std::max(0.0, std::min(hi, opl1) - std::max(lo, opl0)) / length
                                  : (opl0 >= lo && opl0 < hi ? 1.0 : 0.0);
      bins[b] += share * value.g;
    }
  }
  double horizon() const override { return Infinity; }
  const TimeGrid& timeGrid() const override { return grid_; }

  double total = 0.0;

 private:
  double start_, width_;
  TimeGrid grid_;

 public:
  std::vector<double> bins;
};

std::shared_ptr<Scene> singleScatteringScene(const SingleScattering& model) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value=")", model.sigmaT, R"("/><float name="albedo" value=")",
                             model.sigmaS / model.sigmaT, R"("/></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x=")", model.light.x, R"(" y=")", model.light.y, R"(" z=")",
                             model.light.z, R"("/><float name="intensity" value=")", model.intensity, R"("/></emitter>
</scene>)"));
}

struct PassStatistics {
  Mean total;
  std::vector<Mean> bins;
};

/// Passes of `photons` photons at kernel radius `radius`; max_depth 2 keeps
/// single scattering only. Photon points are cheap: all photons leave them.
beams::BeamSettings singleScatteringSettings(float radius, int photons,
                                             beams::VolumeEstimator estimator = beams::VolumeEstimator::Beams) {
  beams::BeamSettings settings;
  settings.photonCount = photons;
  settings.radius = settings.surfaceRadius = radius;
  settings.maxDepth = 2;
  settings.volumeEstimator = estimator;
  if (estimator == beams::VolumeEstimator::Points) settings.beamPhotonCount = 0;
  return settings;
}

/// `passes` independent passes with `settings`, one camera ray each.
PassStatistics estimate(const Scene& scene, const Vec3f& d, const beams::BeamSettings& settings, int passes,
                        double start, double width, int bins) {
  PassStatistics stats;
  stats.bins.resize(size_t(bins));
  auto sampler = seededSampler(3);
  for (int i = 0; i < passes; ++i) {
    beams::BeamPass pass(scene, settings, 0, uint64_t(1000 + i), Infinity);
    HistogramRecorder recorder(start, width, bins);
    pass.sample(scene, Ray(Point3f(0.0f), d), *sampler, recorder);
    stats.total.add(recorder.total);
    for (int b = 0; b < bins; ++b) stats.bins[size_t(b)].add(recorder.bins[size_t(b)]);
  }
  return stats;
}

/// Single scattering seen by one ray against its closed form: with radius
/// 0.5 (16 passes of `widePhotons`) the kernel's bias shows (> 5 sigma), with
/// 0.03 (`narrowPasses` of `narrowPhotons`) the estimate agrees within 5 sigma
/// in total and in each of 12 OPL bins spanning `width` from the first arrival.
void expectConvergenceAsTheRadiusShrinks(beams::VolumeEstimator estimator, int widePhotons, int narrowPhotons,
                                         int narrowPasses, double width) {
  const Vec3f d = normalize(Vec3f(0.3f, 0.1f, 1.0f));
  SingleScattering model{d};
  auto scene = singleScatteringScene(model);
  const double tau0 = model.tau(0.0);
  const int bins = 12;
  const double exact = model.binIntegral(tau0, tau0 + 200.0);
  PassStatistics wide =
      estimate(*scene, d, singleScatteringSettings(0.5f, widePhotons, estimator), 16, tau0, width / bins, bins);
  PassStatistics narrow = estimate(*scene, d, singleScatteringSettings(0.03f, narrowPhotons, estimator), narrowPasses,
                                   tau0, width / bins, bins);
  double wideError = std::abs(wide.total.mean() - exact), narrowError = std::abs(narrow.total.mean() - exact);
  std::printf("%s: exact %.6g; radius 0.5: %.6g +- %.2g; radius 0.03: %.6g +- %.2g\n",
              estimator == beams::VolumeEstimator::Points ? "points" : "beams", exact, wide.total.mean(),
              wide.total.standardError(), narrow.total.mean(), narrow.total.standardError());
  EXPECT_LT(narrowError, wideError) << "the error falls with the radius";
  EXPECT_GT(wideError, 5.0 * wide.total.standardError()) << "the wide kernel's bias is visible";
  EXPECT_LT(narrowError, 5.0 * narrow.total.standardError());
  for (int b = 0; b < bins; ++b) {
    double t0 = tau0 + width * b / bins, t1 = tau0 + width * (b + 1) / bins;
    expectWithinErrorBars(narrow.bins[size_t(b)], model.binIntegral(t0, t1), 1e-7, str("bin ", b, " [", t0, ", ", t1, ")"));
  }
}

}  // namespace

TEST(TransientBeamsMedia, SingleScatteringConvergesToTheClosedFormAsTheRadiusShrinks) {
  expectConvergenceAsTheRadiusShrinks(beams::VolumeEstimator::Beams, 20000, 60000, 12, 6.0);
}

TEST(TransientBeamsMedia, PhotonPointsConvergeToTheClosedFormAsTheRadiusShrinks) {
  // volume_estimator = points: the beam radiance estimate over photons at
  // their scattering vertices (ray_point.h), the same closed form; its 2D
  // kernel blurs the in-scattered light across the ray. Points are cheap:
  // more photons. A point lands in one bin, so a bin's error bar needs hits
  // in several passes: the bins span the first 3 OPL units of arrivals (over
  // 99 % of the light), where each pass puts points in every bin; later, a
  // bin may see none in 16 passes and have no error bar at all.
  expectConvergenceAsTheRadiusShrinks(beams::VolumeEstimator::Points, 20000, 200000, 16, 3.0);
}

TEST(TransientBeamsMedia, WithoutObserverTimeOnlyTheLightsPathCounts) {
  // observer_time = false drops the camera segment from the OPL: the same
  // beams give the same radiance, now arriving at the light path's OPL alone,
  // which is at least the light's distance from the camera ray (minus the
  // kernel radius), and earlier than with the camera segment.
  const Vec3f d = normalize(Vec3f(0.3f, 0.1f, 1.0f));
  SingleScattering model{d};
  auto scene = singleScatteringScene(model);
  beams::BeamSettings settings;
  settings.photonCount = 20000;
  settings.radius = settings.surfaceRadius = 0.05f;
  settings.maxDepth = 2;
  beams::BeamSettings unwarped = settings;
  unwarped.observerTime = false;
  beams::BeamPass with(*scene, settings, 0, 77, Infinity), without(*scene, unwarped, 0, 77, Infinity);
  auto withSampler = seededSampler(8), withoutSampler = seededSampler(8);
  CollectingRecorder a, b;
  with.sample(*scene, Ray(Point3f(0.0f), d), *withSampler, a);
  without.sample(*scene, Ray(Point3f(0.0f), d), *withoutSampler, b);
  ASSERT_EQ(a.hits.size(), b.hits.size());
  ASSERT_GT(a.hits.size(), 100u);
  EXPECT_NEAR(a.total().g, b.total().g, 1e-6f * a.total().g);
  const Vec3f toLight = model.light - Point3f(0.0f);
  const double lineDistance = length(toLight - d * dot(toLight, d));
  double meanShift = 0.0;
  for (size_t i = 0; i < a.hits.size(); ++i) {
    EXPECT_GE(b.hits[i].first, lineDistance - settings.radius - 1e-4);
    EXPECT_LT(b.hits[i].first, a.hits[i].first);
    meanShift += (a.hits[i].first - b.hits[i].first) / double(a.hits.size());
  }
  EXPECT_GT(meanShift, 0.5) << "the camera segments' length, on average";
}

TEST(TransientBeamsMedia, EmitterPulseOffsetShiftsEveryContribution) {
  // Photons leave at OPL 0 and contributions carry their emitter's pulse: a
  // delta pulse at OPL 1.5 shifts every beam estimate by exactly 1.5.
  const Vec3f d = normalize(Vec3f(0.3f, 0.1f, 1.0f));
  SingleScattering model{d};
  auto plain = singleScatteringScene(model);
  auto delayed = loadSceneStrict(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value="0.8"/><float name="albedo" value="0.75"/></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x="0.8" y="0" z="1"/><float name="intensity" value="2"/>
    <float name="pulse_offset" value="1.5"/></emitter>
</scene>)");
  beams::BeamSettings settings;
  settings.photonCount = 20000;
  settings.radius = settings.surfaceRadius = 0.05f;
  settings.maxDepth = 2;
  beams::BeamPass a(*plain, settings, 0, 5, Infinity), b(*delayed, settings, 0, 5, Infinity);
  auto samplerA = seededSampler(4), samplerB = seededSampler(4);
  CollectingRecorder ra, rb;
  a.sample(*plain, Ray(Point3f(0.0f), d), *samplerA, ra);
  b.sample(*delayed, Ray(Point3f(0.0f), d), *samplerB, rb);
  ASSERT_EQ(ra.hits.size(), rb.hits.size());
  ASSERT_GT(ra.hits.size(), 100u);
  for (size_t i = 0; i < ra.hits.size(); ++i) {
    EXPECT_NEAR(rb.hits[i].first, ra.hits[i].first + 1.5, 1e-9);
    EXPECT_EQ(rb.hits[i].second, ra.hits[i].second);
  }
}

namespace {

/// The single-scattering scene of `model` with a phase function that delays
/// every scattering by `delay` plus an exponential time of mean `lifetime`.
std::shared_ptr<Scene> delayedScatteringScene(const SingleScattering& model, double delay, double lifetime) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value=")", model.sigmaT, R"("/><float name="albedo" value=")",
                             model.sigmaS / model.sigmaT, R"("/><phase type="isotropic"><float name="delay" value=")",
                             delay, R"("/><float name="lifetime" value=")", lifetime, R"("/></phase></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x=")", model.light.x, R"(" y=")", model.light.y, R"(" z=")",
                             model.light.z, R"("/><float name="intensity" value=")", model.intensity, R"("/></emitter>
</scene>)"));
}

}  // namespace

TEST(TransientBeamsMedia, PhaseDelayShiftsSingleScatteringByExactlyTheDelay) {
  // Single scattering (max_depth 2) scatters once, toward the camera: a
  // constant phase delay moves every ray x beam estimate by exactly that
  // delay, and an exponential lifetime by a time whose mean is the lifetime
  // (5 sigma; sigma = lifetime / sqrt(n)); the values do not change.
  const Vec3f d = normalize(Vec3f(0.3f, 0.1f, 1.0f));
  SingleScattering model{d};
  const double delay = 0.7, lifetime = 0.4;
  auto plain = singleScatteringScene(model), delayed = delayedScatteringScene(model, delay, 0.0),
       living = delayedScatteringScene(model, 0.0, lifetime);
  beams::BeamSettings settings;
  settings.photonCount = 20000;
  settings.radius = settings.surfaceRadius = 0.05f;
  settings.maxDepth = 2;
  beams::BeamPass a(*plain, settings, 0, 5, Infinity), b(*delayed, settings, 0, 5, Infinity),
      c(*living, settings, 0, 5, Infinity);
  auto samplerA = seededSampler(4), samplerB = seededSampler(4), samplerC = seededSampler(4);
  CollectingRecorder ra, rb, rc;
  a.sample(*plain, Ray(Point3f(0.0f), d), *samplerA, ra);
  b.sample(*delayed, Ray(Point3f(0.0f), d), *samplerB, rb);
  c.sample(*living, Ray(Point3f(0.0f), d), *samplerC, rc);
  ASSERT_GT(ra.hits.size(), 100u);
  ASSERT_EQ(ra.hits.size(), rb.hits.size());
  ASSERT_EQ(ra.hits.size(), rc.hits.size());
  Mean shift;
  for (size_t i = 0; i < ra.hits.size(); ++i) {
    EXPECT_NEAR(rb.hits[i].first, ra.hits[i].first + delay, 1e-6 * delay);  // the delay is a float parameter
    EXPECT_EQ(rb.hits[i].second, ra.hits[i].second);
    EXPECT_EQ(rc.hits[i].second, ra.hits[i].second);
    const double s = rc.hits[i].first - ra.hits[i].first;
    EXPECT_GE(s, -1e-9);
    shift.add(s);
  }
  EXPECT_NEAR(shift.mean(), lifetime, 5.0 * lifetime / std::sqrt(double(shift.count())));
}
