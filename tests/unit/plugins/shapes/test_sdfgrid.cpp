// sdfgrid (Mitsuba 3's signed distance grid), triangulated by marching
// tetrahedra: a sphere's distance sampled on a grid gives a closed,
// outward-wound mesh whose area and enclosed volume converge to the sphere's
// at second order in the cell size (the error bound below is that of a
// triangulation inscribed in a smooth surface: ~ curvature x cell^2 per unit
// area), smooth normals are the sphere's; bad files are clear errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <utility>

#include <femto/math/constants.h>
#include <femto/render/mesh.h>

#include "plugin_util.h"
#include "render_test_util.h"

using namespace femto;
namespace fs = std::filesystem;

namespace {

constexpr float Radius = 0.3f;

/// A .vol of the distance to a sphere of Radius around (0.5, 0.5, 0.5) on an n^3 grid over the unit cube.
fs::path sphereGrid(const fs::path& dir, int n, int channels = 1) {
  fs::path file = dir / ("sphere" + std::to_string(n) + ".vol");
  std::ofstream out(file, std::ios::binary);
  out.write("VOL\x03", 4);
  const int32_t header[5] = {1, n, n, n, channels};
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  const float box[6] = {0, 0, 0, 1, 1, 1};
  out.write(reinterpret_cast<const char*>(box), sizeof box);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        Point3f p(float(x) / float(n - 1), float(y) / float(n - 1), float(z) / float(n - 1));
        float d = length(p - Point3f(0.5f)) - Radius;
        for (int c = 0; c < channels; ++c) out.write(reinterpret_cast<const char*>(&d), sizeof d);
      }
  return file;
}

std::shared_ptr<TriangleMesh> load(const fs::path& file, const std::string& normals = "smooth") {
  Properties props("sdfgrid");
  props.setString("filename", file.string());
  props.setString("normals", normals);
  return std::dynamic_pointer_cast<TriangleMesh>(test::createPlugin<Shape>(ObjectKind::Shape, props));
}

/// Volume enclosed by the mesh (divergence theorem) and whether every edge
/// is shared by exactly two triangles with opposite directions (closed, consistently wound).
std::pair<double, bool> volumeAndClosed(const TriangleMesh& mesh) {
  const auto& p = mesh.positions();
  const auto& idx = mesh.indices();
  double volume = 0.0;
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t < idx.size(); t += 3) {
    const Point3f &a = p[idx[t]], &b = p[idx[t + 1]], &c = p[idx[t + 2]];
    volume += dot(Vec3f(a), cross(Vec3f(b), Vec3f(c))) / 6.0;
    for (int e = 0; e < 3; ++e) ++edges[{idx[t + e], idx[t + (e + 1) % 3]}];
  }
  bool closed = true;
  for (const auto& [edge, count] : edges) {
    auto twin = edges.find({edge.second, edge.first});
    closed &= count == 1 && twin != edges.end() && twin->second == 1;
  }
  return {volume, closed};
}

}  // namespace

TEST(SdfGrid, SphereConvergesAtSecondOrderAndIsClosed) {
  auto dir = test::scratchDir("sdfgrid");
  const double area = 4.0 * Pi * Radius * Radius, volume = 4.0 / 3.0 * Pi * Radius * Radius * Radius;
  double previousError = 1.0;
  for (int n : {17, 33, 65}) {
    SCOPED_TRACE(n);
    auto mesh = load(sphereGrid(dir, n));
    ASSERT_TRUE(mesh);
    auto [v, closed] = volumeAndClosed(*mesh);
    EXPECT_TRUE(closed) << "every edge shared by two triangles, wound oppositely";
    EXPECT_GT(v, 0.0) << "outward winding encloses a positive volume";
    // Inscribed triangles cut corners: area and volume below the sphere's by
    // ~ (cell / radius)^2 (measured: a quarter of it for the area, half for the volume).
    const double h = 1.0 / (n - 1), bound = (h / Radius) * (h / Radius);
    const double areaError = std::abs(mesh->surfaceArea() - area) / area;
    std::cout << n << "^3 grid: area off by " << areaError << ", volume by " << std::abs(v - volume) / volume
              << " (bound " << bound << ")\n";
    EXPECT_LT(areaError, bound);
    EXPECT_LT(std::abs(v - volume) / volume, bound);
    // Second order: halving the cell divides the error by about 4.
    if (n > 17) EXPECT_LT(areaError, previousError / 2.5);
    previousError = areaError;
  }
}

TEST(SdfGrid, SmoothNormalsAreTheSpheresAndVerticesLieOnIt) {
  auto dir = test::scratchDir("sdfgrid-normals");
  auto mesh = load(sphereGrid(dir, 33));
  ASSERT_EQ(mesh->normals().size(), mesh->positions().size());
  for (size_t i = 0; i < mesh->positions().size(); ++i) {
    const Vec3f radial = mesh->positions()[i] - Point3f(0.5f);
    // Vertices sit where the samples' linear interpolation crosses zero: on the
    // sphere to the interpolation's error, ~ h^2 / (2 r).
    EXPECT_NEAR(length(radial), Radius, 0.5 * (1.0 / 32) * (1.0 / 32) / Radius + 1e-5);
    EXPECT_GT(dot(Vec3f(mesh->normals()[i]), radial / length(radial)), 0.99f);
  }
  EXPECT_TRUE(load(sphereGrid(dir, 33), "analytic")->normals().empty());
}

TEST(SdfGrid, BadFilesAreClearErrors) {
  auto dir = test::scratchDir("sdfgrid-bad");
  auto errorOf = [&](const fs::path& file, const std::string& normals = "smooth") {
    return test::errorMessageOf([&] { load(file, normals); });
  };
  EXPECT_NE(errorOf(sphereGrid(dir, 9, 3)).find("has 3 channels"), std::string::npos);
  EXPECT_NE(errorOf(dir / "missing.vol").find("cannot open"), std::string::npos);
  EXPECT_NE(errorOf(sphereGrid(dir, 9), "flat").find("normals"), std::string::npos);
  // A grid whose distance never changes sign has no surface.
  fs::path empty = dir / "empty.vol";
  {
    std::ofstream out(empty, std::ios::binary);
    out.write("VOL\x03", 4);
    const int32_t header[5] = {1, 2, 2, 2, 1};
    out.write(reinterpret_cast<const char*>(header), sizeof header);
    const float box[6] = {0, 0, 0, 1, 1, 1};
    out.write(reinterpret_cast<const char*>(box), sizeof box);
    const float one = 1.0f;
    for (int i = 0; i < 8; ++i) out.write(reinterpret_cast<const char*>(&one), sizeof one);
  }
  EXPECT_NE(errorOf(empty).find("no zero crossing"), std::string::npos);
}
