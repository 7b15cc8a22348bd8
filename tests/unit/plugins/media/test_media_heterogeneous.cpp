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

}  // namespace

TEST(MediaHeterogeneous, TrackingMatchesQuadrature) {
  auto dir = scratchDir("heterogeneous");
  writeVol(dir / "grid.vol", 1);
  for (const char* version : {"0.6.0", "3.0.0"}) {
    SCOPED_TRACE(version);
    auto scene = heterogeneousScene(dir, version);
    const Medium& medium = *scene->sensor().medium();
    Color3f sigmaT = std::string(version) == "0.6.0" ? Color3f(0.4f, 0.6f, 0.6f) * 0.5f : Color3f(0.2f);
    Color3f albedo = std::string(version) == "0.6.0" ? Color3f(0.75f, 1.0f / 6.0f, 1.0f) : Color3f(0.75f, 0.2f, 1.0f);
    // A ray crossing the box (world [-1, 1] x [-0.5, 0.5] x [-0.5, 0.5]) obliquely, starting outside it.
    Ray ray(Point3f(-1.5f, -0.7f, -0.2f), normalize(Vec3f(1.0f, 0.45f, 0.2f)));
    const float tMax = 2.6f;
    auto density = [&](double t) {
      Point3f world = ray(float(t));
      Point3f local = world + Vec3f(1.0f, 0.5f, 0.5f);
      bool inside = local.x >= 0 && local.x <= 2 && local.y >= 0 && local.y <= 1 && local.z >= 0 && local.z <= 1;
      return inside ? field(local) : 0.0;
    };
    auto sampler = seededSampler(21);
    Mean ratio[3], crossed[3], scattered[3];
    for (int i = 0; i < 100000; ++i) {
      Color3f tr = medium.transmittance(ray, tMax, *sampler);
      MediumSample ms = medium.sampleDistance(ray, tMax, *sampler);
      for (int c = 0; c < 3; ++c) {
        ratio[c].add(tr[c]);
        crossed[c].add(ms.scattered ? 0.0 : ms.weight[c]);
        scattered[c].add(ms.scattered ? ms.weight[c] : 0.0);
      }
    }
    // The ray is inside the box for t in [t0, t1] (slab method); there the
    // density is a cubic polynomial in t, which Simpson's rule integrates exactly.
    double t0 = 0.0, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
      double lo = (Vec3f(-1, -0.5f, -0.5f)[a] - ray.o[a]) / ray.d[a], hi = (Vec3f(1, 0.5f, 0.5f)[a] - ray.o[a]) / ray.d[a];
      t0 = std::max(t0, std::min(lo, hi));
      t1 = std::min(t1, std::max(lo, hi));
    }
    ASSERT_LT(t0, t1);
    auto depthTo = [&](double t) { return integrate(density, t0, std::clamp(t, t0, t1), 64); };
    for (int c = 0; c < 3; ++c) {
      double depth = sigmaT[c] * depthTo(t1);
      // E[weight at scattering] = integral of sigma_s(t) T(0, t) dt.
      double scatter = integrate(
          [&](double t) { return albedo[c] * sigmaT[c] * density(t) * std::exp(-sigmaT[c] * depthTo(t)); }, t0, t1, 512);
      expectWithinErrorBars(ratio[c], std::exp(-depth), 1e-5, str("ratio tracking, channel ", c));
      expectWithinErrorBars(crossed[c], std::exp(-depth), 1e-5, str("free-flight crossing, channel ", c));
      expectWithinErrorBars(scattered[c], scatter, 1e-5, str("free-flight scattering, channel ", c));
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
