// scenes/glass-delay: loads strictly, renders, and shows the refraction delay.
// Looking through the glass sphere's centre at the back wall, the wall's
// direct light arrives later than light from the wall beside the sphere by
// the extra optical path of the glass, (eta - 1) x chord; both peaks are
// checked against optical path lengths computed here from the scene's
// geometry (ray-sphere intersection and Snell's law, independent of the
// renderer's transport code).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"
#include "transient_film_test_util.h"

using namespace femto;

namespace {

// The geometry of scenes/glass-delay/scene.xml (its header comment lists it).
struct D3 {
  double x, y, z;
  D3 operator+(const D3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  D3 operator-(const D3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  D3 operator*(double s) const { return {x * s, y * s, z * s}; }
};
double dot(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(const D3& a) { return std::sqrt(dot(a, a)); }
D3 normalized(const D3& a) { return a * (1.0 / length(a)); }

const D3 SphereCentre{0, 0, 0};
constexpr double Radius = 0.5, Eta = 1.5, WallZ = -1.0;
const D3 Light{-1.2, 1.6, 1.2};

/// Distance along the unit ray (o, d) to its first intersection with the
/// sphere, if any (`inside`: the origin is inside, take the far root).
std::optional<double> hitSphere(const D3& o, const D3& d, bool inside) {
  D3 oc = o - SphereCentre;
  double b = dot(oc, d), c = dot(oc, oc) - Radius * Radius, disc = b * b - c;
  if (disc < 0.0) return std::nullopt;
  double t = inside ? -b + std::sqrt(disc) : -b - std::sqrt(disc);
  return t > 0.0 ? std::optional<double>(t) : std::nullopt;
}

/// Snell's law: unit `d` refracted at unit normal `n` (facing against d), index ratio eta = n_i / n_t.
D3 refract(const D3& d, const D3& n, double eta) {
  double cosi = -dot(d, n), k = 1.0 - eta * eta * (1.0 - cosi * cosi);
  EXPECT_GE(k, 0.0) << "no total internal reflection on the paths used here";
  return d * eta + n * (eta * cosi - std::sqrt(std::max(0.0, k)));
}

struct WallPath {
  double opl;           // camera -> (glass) -> wall point -> light
  double glassChord;    // geometric length inside the glass (0: the ray misses the sphere)
  D3 wallPoint;
};

/// The optical path of the light that reaches the camera along the unit ray
/// (o, d) from the back wall, lit directly by the point light: refracted
/// through the sphere if the ray meets it (the Fresnel-transmitted path).
WallPath wallPath(D3 o, D3 d) {
  WallPath path{0.0, 0.0, {}};
  if (auto t = hitSphere(o, d, false)) {
    D3 entry = o + d * *t;
    D3 inside = refract(d, normalized(entry - SphereCentre), 1.0 / Eta);
    double chord = *hitSphere(entry, inside, true);
    D3 exit = entry + inside * chord;
    path.opl += *t + Eta * chord;
    path.glassChord = chord;
    d = refract(inside, normalized(SphereCentre - exit), Eta);
    o = exit;
  }
  double toWall = (WallZ - o.z) / d.z;
  path.wallPoint = o + d * toWall;
  path.opl += toWall + length(Light - path.wallPoint);
  return path;
}

D3 toD3(const Vec3f& v) { return {v.x, v.y, v.z}; }

/// The camera ray through the centre of pixel (x, y).
std::pair<D3, D3> pixelRay(const Scene& scene, int x, int y) {
  Ray ray;
  scene.sensor().sampleRay(Point2f(x + 0.5f, y + 0.5f), Point2f(0.5f, 0.5f), ray);
  return {toD3(Vec3f(ray.o.x, ray.o.y, ray.o.z)), normalized(toD3(ray.d))};
}

}  // namespace

TEST(GlassDelayScene, LightThroughTheSphereArrivesLaterByTheGlassDelay) {
  // Odd resolution: the centre pixel's ray is the camera axis, through the
  // sphere's centre (chord = diameter). Pixels ~0.045 units wide at the wall
  // keep the spread of path lengths inside one pixel below a bin.
  constexpr int Resolution = 81, Bins = 160;
  constexpr double Start = 3.0, BinWidth = 0.05;
  auto dir = test::scratchDir("glass-delay");
  LoadOptions options;
  options.strict = true;
  options.defines = {{"resolution", std::to_string(Resolution)}, {"spp", "16"}, {"bins", std::to_string(Bins)},
                     {"bin_width", "0.05"}, {"start", "3"}, {"frames", "false"}};
  auto scene = loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/glass-delay/scene.xml", options);
  RenderOptions render;
  render.output = dir / "glass.exr";
  render.progress = false;
  RenderStats stats = scene->integrator().render(*scene, render);
  ASSERT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  int h = 0, w = 0, bins = 0;
  std::vector<float> volume = test::readVolume(dir / "glass.npy", h, w, bins);
  ASSERT_EQ(w, Resolution);
  ASSERT_EQ(bins, Bins);

  // The OPL at the centre of the brightest bin of pixel (x, y).
  auto peakOpl = [&](int x, int y) {
    int best = 0;
    double bestValue = -1.0;
    for (int b = 0; b < bins; ++b) {
      const float* v = &volume[((size_t(y) * w + x) * bins + b) * 3];
      double sum = double(v[0]) + v[1] + v[2];
      if (sum > bestValue) bestValue = sum, best = b;
    }
    EXPECT_GT(bestValue, 0.0) << "pixel " << x << "," << y << " received no light";
    return Start + (best + 0.5) * BinWidth;
  };

  const int centre = Resolution / 2;
  auto [o, d] = pixelRay(*scene, centre, centre);
  WallPath through = wallPath(o, d);
  ASSERT_NEAR(through.glassChord, 2.0 * Radius, 1e-4) << "the centre pixel looks through the sphere's centre";

  // Beside the sphere, on the light's side (away from the mirror): the pixel
  // of the centre row whose wall point is nearest x = -0.9, clear of the sphere.
  int besideX = -1;
  WallPath beside{};
  for (int x = 0; x < Resolution; ++x) {
    auto [bo, bd] = pixelRay(*scene, x, centre);
    WallPath p = wallPath(bo, bd);
    if (p.glassChord == 0.0 && (besideX < 0 || std::abs(p.wallPoint.x + 0.9) < std::abs(beside.wallPoint.x + 0.9)))
      besideX = x, beside = p;
  }
  ASSERT_GE(besideX, 0);

  double measuredThrough = peakOpl(centre, centre), measuredBeside = peakOpl(besideX, centre);
  std::printf("through the sphere: peak at OPL %.3f, expected %.4f; beside (pixel %d): %.3f, expected %.4f\n",
              measuredThrough, through.opl, besideX, measuredBeside, beside.opl);
  // Each peak within one bin of its analytic arrival...
  EXPECT_NEAR(measuredThrough, through.opl, BinWidth);
  EXPECT_NEAR(measuredBeside, beside.opl, BinWidth);
  // ...and the delay between them is the geometric difference of the two
  // paths plus the glass's (eta - 1) x chord = 0.5 (ten bins), up to one bin
  // (both peaks are bin centres): ignoring the glass's index would miss by
  // nine bins or more.
  double glassDelay = (Eta - 1.0) * through.glassChord;
  double geometric = (through.opl - glassDelay) - beside.opl;
  EXPECT_NEAR(measuredThrough - measuredBeside, geometric + glassDelay, BinWidth);
  EXPECT_GT(measuredThrough - measuredBeside - geometric, glassDelay - BinWidth);
}
