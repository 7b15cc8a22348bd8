// Grid volumes and the heterogeneous medium: a .vol file written here is read
// back with exact trilinear values, bad files are reported, and ratio
// tracking (transmittance) and spectral/delta tracking (free flights) match
// numerical quadrature of the optical depth.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>

#include <femto/render/volume.h>

#include "media_test_util.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

/// A multilinear function: trilinear interpolation of its vertex samples
/// reproduces it exactly, so it is the closed form of the grid lookups.
double field(const Point3f& p) {
  double x = p.x, y = p.y, z = p.z;
  return 1.0 + 2.0 * x - y + 0.5 * z + 0.3 * x * y - 0.2 * y * z + 0.1 * x * y * z;
}

const int Res[3] = {3, 2, 2};
const Point3f Min(0, 0, 0), Max(2, 1, 1);

void writeVol(const std::filesystem::path& file, int channels, const char* magic = "VOL", int version = 3,
              size_t dropFloats = 0) {
  std::ofstream out(file, std::ios::binary);
  out.write(magic, 3);
  char v = char(version);
  out.write(&v, 1);
  int32_t header[5] = {1, Res[0], Res[1], Res[2], channels};
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  float bounds[6] = {Min.x, Min.y, Min.z, Max.x, Max.y, Max.z};
  out.write(reinterpret_cast<const char*>(bounds), sizeof bounds);
  std::vector<float> data;
  for (int z = 0; z < Res[2]; ++z)
    for (int y = 0; y < Res[1]; ++y)
      for (int x = 0; x < Res[0]; ++x) {
        Point3f p(Min.x + (Max.x - Min.x) * x / (Res[0] - 1), Min.y + (Max.y - Min.y) * y / (Res[1] - 1),
                  Min.z + (Max.z - Min.z) * z / (Res[2] - 1));
        for (int c = 0; c < channels; ++c) data.push_back(float(field(p) * (c + 1)));
      }
  data.resize(data.size() - dropFloats);
  out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size() * sizeof(float)));
}

std::shared_ptr<Volume> gridVolume(const std::filesystem::path& file, const Transform& toWorld = Transform()) {
  Properties props("gridvolume");
  props.setString("filename", file.string());
  props.setTransform("to_world", toWorld);
  return makePlugin<Volume>(ObjectKind::Volume, props);
}

/// Optical depth of sigma(t) along [0, tMax] by composite Simpson's rule.
template <typename F>
double integrate(F&& f, double a, double b, int n = 4000) {
  double h = (b - a) / n, sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += f(a + i * h) * (i % 2 ? 4.0 : 2.0);
  return sum * h / 3.0;
}

}  // namespace

TEST(MediaGridVolume, TrilinearLookupIsExactForMultilinearData) {
  auto dir = scratchDir("gridvolume");
  writeVol(dir / "grid.vol", 1);
  writeVol(dir / "rgb.vol", 3);
  const Vec3f offset(1.0f, -2.0f, 0.5f);
  auto grid = gridVolume(dir / "grid.vol", Transform::translate(offset));
  auto rgb = gridVolume(dir / "rgb.vol");
  for (Point3f local : {Point3f(0, 0, 0), Point3f(2, 1, 1), Point3f(1, 0, 1), Point3f(0.25f, 0.5f, 0.75f),
                        Point3f(1.7f, 0.1f, 0.3f), Point3f(2.0f, 0.5f, 0.0f)}) {
    EXPECT_NEAR(grid->evalFloat(local + offset), field(local), 1e-5) << local;
    Color3f c = rgb->evalColor(local);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], field(local) * (k + 1), 1e-5) << local;
    EXPECT_NEAR(rgb->evalFloat(local), 2.0 * field(local), 1e-5) << local;
  }
  EXPECT_EQ(grid->evalFloat(Point3f(-0.1f, 0.5f, 0.5f) + offset), 0.0f);
  EXPECT_EQ(grid->evalFloat(Point3f(1.0f, 1.01f, 0.5f) + offset), 0.0f);
  double largest = 0.0;  // the majorant is the largest sample (vertices of the 3x2x2 grid)
  for (float x : {0.0f, 1.0f, 2.0f})
    for (float y : {0.0f, 1.0f})
      for (float z : {0.0f, 1.0f}) largest = std::max(largest, field(Point3f(x, y, z)));
  EXPECT_FLOAT_EQ(grid->maxFloat(), float(largest));
  EXPECT_EQ(grid->bbox().min, Min + offset);
  EXPECT_EQ(grid->bbox().max, Max + offset);
  std::filesystem::remove_all(dir);
}

TEST(MediaGridVolume, BadFilesAreReported) {
  auto dir = scratchDir("gridvolume-bad");
  writeVol(dir / "magic.vol", 1, "VOX");
  writeVol(dir / "version.vol", 1, "VOL", 2);
  writeVol(dir / "short.vol", 1, "VOL", 3, 5);
  EXPECT_NE(errorMessageOf([&] { gridVolume(dir / "missing.vol"); }).find("cannot open"), std::string::npos);
  EXPECT_NE(errorMessageOf([&] { gridVolume(dir / "magic.vol"); }).find("VOL"), std::string::npos);
  EXPECT_NE(errorMessageOf([&] { gridVolume(dir / "version.vol"); }).find("version 2"), std::string::npos);
  EXPECT_NE(errorMessageOf([&] { gridVolume(dir / "short.vol"); }).find("truncated"), std::string::npos);
  std::filesystem::remove_all(dir);
}

namespace {

std::shared_ptr<Scene> heterogeneousScene(const std::filesystem::path& dir, const std::string& version) {
  // 0.6 form: a density volume and sigma_s/sigma_a colours; the grid moved by to_world.
  if (version == "0.6.0")
    return sceneWithMedium(R"(<medium id="m" type="heterogeneous">
        <volume name="density" type="gridvolume"><string name="filename" value="grid.vol"/>
          <transform name="toWorld"><translate x="-1" y="-0.5" z="-0.5"/></transform></volume>
        <rgb name="sigmaS" value="0.3, 0.1, 0.6"/><rgb name="sigmaA" value="0.1, 0.5, 0.0"/>
        <float name="scale" value="0.5"/></medium>)", version, dir);
  // Mitsuba 3 form: the field as sigma_t, with an albedo.
  return sceneWithMedium(R"(<medium id="m" type="heterogeneous">
      <volume name="sigma_t" type="gridvolume"><string name="filename" value="grid.vol"/>
        <transform name="to_world"><translate x="-1" y="-0.5" z="-0.5"/></transform></volume>
      <rgb name="albedo" value="0.75, 0.2, 1.0"/><float name="scale" value="0.2"/></medium>)", version, dir);
}

/// A ray crossing the grid's box (world [-1, 1] x [-0.5, 0.5] x [-0.5, 0.5])
/// obliquely, starting outside it, and the closed forms along it: inside the
/// box, for t in [t0, t1] (slab method), the density is a cubic polynomial in
/// t, which Simpson's rule integrates exactly.
struct ObliqueCrossing {
  Ray ray{Point3f(-1.5f, -0.7f, -0.2f), normalize(Vec3f(1.0f, 0.45f, 0.2f))};
  double t0 = 0.0, t1 = 0.0;

  explicit ObliqueCrossing(double tMax) {
    t1 = tMax;
    for (int a = 0; a < 3; ++a) {
      double lo = (Vec3f(-1, -0.5f, -0.5f)[a] - ray.o[a]) / ray.d[a], hi = (Vec3f(1, 0.5f, 0.5f)[a] - ray.o[a]) / ray.d[a];
      t0 = std::max(t0, std::min(lo, hi));
      t1 = std::min(t1, std::max(lo, hi));
    }
  }
  double density(double t) const {
    Point3f local = ray(float(t)) + Vec3f(1.0f, 0.5f, 0.5f);
    bool inside = local.x >= 0 && local.x <= 2 && local.y >= 0 && local.y <= 1 && local.z >= 0 && local.z <= 1;
    return inside ? field(local) : 0.0;
  }
  double depthTo(double t) const {
    return integrate([&](double u) { return density(u); }, t0, std::clamp(t, t0, t1), 64);
  }
  /// E[weight at scattering before `end`] = integral of sigma_s(t) T(0, t) t^power dt over [0, end).
  double scattering(double sigmaT, double albedo, double end, int power = 0) const {
    return integrate(
        [&](double t) {
          return albedo * sigmaT * density(t) * std::exp(-sigmaT * depthTo(t)) * std::pow(t, power);
        },
        t0, std::clamp(end, t0, t1), 512);
  }
};

Color3f sigmaTOf(const std::string& version) {
  return version == "0.6.0" ? Color3f(0.4f, 0.6f, 0.6f) * 0.5f : Color3f(0.2f);
}
Color3f albedoOf(const std::string& version) {
  return version == "0.6.0" ? Color3f(0.75f, 1.0f / 6.0f, 1.0f) : Color3f(0.75f, 0.2f, 1.0f);
}

}  // namespace

TEST(MediaHeterogeneous, TrackingMatchesQuadrature) {
  auto dir = scratchDir("heterogeneous");
  writeVol(dir / "grid.vol", 1);
  for (const char* version : {"0.6.0", "3.0.0"}) {
    SCOPED_TRACE(version);
    auto scene = heterogeneousScene(dir, version);
    const Medium& medium = *scene->sensor().medium();
    Color3f sigmaT = sigmaTOf(version), albedo = albedoOf(version);
    const float tMax = 2.6f;
    ObliqueCrossing crossing(tMax);
    ASSERT_LT(crossing.t0, crossing.t1);
    auto sampler = seededSampler(21);
    Mean ratio[3], crossed[3], scattered[3];
    for (int i = 0; i < 100000; ++i) {
      Color3f tr = medium.transmittance(crossing.ray, tMax, *sampler);
      MediumSample ms = medium.sampleDistance(crossing.ray, tMax, *sampler);
      for (int c = 0; c < 3; ++c) {
        ratio[c].add(tr[c]);
        crossed[c].add(ms.scattered ? 0.0 : ms.weight[c]);
        scattered[c].add(ms.scattered ? ms.weight[c] : 0.0);
      }
    }
    for (int c = 0; c < 3; ++c) {
      double depth = sigmaT[c] * crossing.depthTo(crossing.t1);
      expectWithinErrorBars(ratio[c], std::exp(-depth), 1e-5, str("ratio tracking, channel ", c));
      expectWithinErrorBars(crossed[c], std::exp(-depth), 1e-5, str("free-flight crossing, channel ", c));
      expectWithinErrorBars(scattered[c], crossing.scattering(sigmaT[c], albedo[c], crossing.t1), 1e-5,
                            str("free-flight scattering, channel ", c));
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(MediaHeterogeneous, FreeFlightsBeforeAReachMatchQuadrature) {
  // Time gating's truncated free flight (Medium::sampleDistanceBefore):
  // conditioned on the first tentative collision before `reach`, weighted by
  // its probability. E[weight t^k] over its scattering events must be the
  // integral over [0, reach) of sigma_s T t^k (k = 0, 1), every event before
  // `reach`, and 1/P times as many samples must scatter as tracking up to
  // `reach` lets (the point of conditioning: fewer wasted paths).
  auto dir = scratchDir("heterogeneous-before");
  writeVol(dir / "grid.vol", 1);
  for (const char* version : {"0.6.0", "3.0.0"}) {
    auto scene = heterogeneousScene(dir, version);
    const Medium& medium = *scene->sensor().medium();
    Color3f sigmaT = sigmaTOf(version), albedo = albedoOf(version);
    ObliqueCrossing crossing(Infinity);
    // Inside the box, past it, and before the ray enters it.
    for (double reach : {crossing.t0 + 0.3 * (crossing.t1 - crossing.t0), crossing.t1 + 0.5, 0.8 * crossing.t0}) {
      SCOPED_TRACE(str(version, ", reach ", reach));
      auto sampler = seededSampler(23);
      Mean zeroth[3], first[3];
      int conditionedScattered = 0, trackedScattered = 0;
      const int n = 100000;
      for (int i = 0; i < n; ++i) {
        MediumSample ms = medium.sampleDistanceBefore(crossing.ray, float(reach), *sampler);
        MediumSample tracked = medium.sampleDistance(crossing.ray, float(reach), *sampler);
        conditionedScattered += ms.scattered;
        trackedScattered += tracked.scattered;
        if (ms.scattered) ASSERT_LT(ms.t, reach);
        else ASSERT_TRUE(ms.weight.isBlack()) << "a crossing carries nothing";
        for (int c = 0; c < 3; ++c) {
          zeroth[c].add(ms.scattered ? ms.weight[c] : 0.0);
          first[c].add(ms.scattered ? ms.weight[c] * ms.t : 0.0);
        }
      }
      for (int c = 0; c < 3; ++c) {
        expectWithinErrorBars(zeroth[c], crossing.scattering(sigmaT[c], albedo[c], reach), 1e-5, str("channel ", c));
        expectWithinErrorBars(first[c], crossing.scattering(sigmaT[c], albedo[c], reach, 1), 1e-5,
                              str("channel ", c, ", first moment"));
      }
      if (reach > crossing.t0) {
        // Conditioning on the first tentative collision (probability P) makes
        // every later step the same: 1/P times as many events scatter.
        double p = -std::expm1(-double(medium.majorant().maxValue()) * (std::min(reach, crossing.t1) - crossing.t0));
        double pc = double(conditionedScattered) / n, pt = double(trackedScattered) / n;
        double se = std::hypot(p * std::sqrt(pc * (1.0 - pc) / n), std::sqrt(pt * (1.0 - pt) / n));
        EXPECT_NEAR(pc * p, pt, 5.0 * se) << "conditioned " << pc << ", tracked " << pt << ", P " << p;
        if (reach < crossing.t1) EXPECT_LT(p, 0.7) << "the case conditions on something";
      } else {
        EXPECT_EQ(conditionedScattered, 0);
      }
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(MediaHeterogeneous, NeedsADensityField) {
  auto dir = scratchDir("heterogeneous-bad");
  writeVol(dir / "grid.vol", 1);
  std::string m = errorMessageOf([&] { sceneWithMedium(R"(<medium id="m" type="heterogeneous"/>)", "3.0.0", dir); });
  EXPECT_NE(m.find("density field"), std::string::npos) << m;
  m = errorMessageOf([&] {
    sceneWithMedium(R"(<medium id="m" type="heterogeneous">
        <volume name="density" type="gridvolume"><string name="filename" value="grid.vol"/></volume>
        <volume name="sigma_t" type="constvolume"/></medium>)", "3.0.0", dir);
  });
  EXPECT_NE(m.find("not both"), std::string::npos) << m;
  std::filesystem::remove_all(dir);
}
