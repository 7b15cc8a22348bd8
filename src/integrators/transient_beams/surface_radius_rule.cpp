#include <transient_beams/surface_radius_rule.h>

#include <algorithm>
#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/render/bsdf.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/transport/volumetric.h>
#include <transient_beams/radius_probe.h>

namespace femto::beams {

namespace {

/// Where the camera ray through `filmPos` meets the plane through p with
/// normal n; false when it runs parallel to it or the sensor gives no ray.
bool onPlane(const Scene& scene, const Point2f& filmPos, const Point3f& p, const Vec3f& n, Point3f& x) {
  Ray ray;
  if (scene.sensor().sampleRay(filmPos, Point2f(0.5f, 0.5f), ray).isBlack()) return false;
  const float along = dot(ray.d, n);
  if (std::abs(along) < 1e-6f) return false;
  x = ray.o + ray.d * (dot(p - ray.o, n) / along);
  return isFinite(x);
}

void appendProbe(const Scene& scene, const Point2f& filmPos, std::vector<SurfaceProbe>& probes) {
  Ray ray;
  if (scene.sensor().sampleRay(filmPos, Point2f(0.5f, 0.5f), ray).isBlack()) return;
  ray = Ray(ray.o, ray.d);
  for (int crossing = 0; crossing < MaxPassThrough; ++crossing) {
    SurfaceInteraction si;
    if (!scene.rayIntersect(ray, si)) return;
    if (isPassThrough(si)) {
      ray = si.spawnRay(ray.d);
      continue;
    }
    const BSDF* bsdf = si.bsdf();
    if (!bsdf || !bsdf->hasSmooth()) return;
    SurfaceProbe probe{si.p, dot(si.n, ray.d) <= 0.0f ? si.n : -si.n};
    // One pixel across and down (straight rays: through index-matched
    // boundaries the camera ray keeps its line).
    Point3f x;
    for (const Point2f& step : {Point2f(1.0f, 0.0f), Point2f(0.0f, 1.0f)})
      if (onPlane(scene, filmPos + Vec2f(step.x, step.y), si.p, Vec3f(si.n), x))
        probe.footprint = std::max(probe.footprint, double(distance(x, si.p)));
    probes.push_back(probe);
    return;
  }
}

double median(std::vector<double> values) {
  const size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + mid, values.end());
  return values[mid];
}

}  // namespace

std::vector<SurfaceProbe> surfaceProbes(const Scene& scene, int grid) {
  std::vector<SurfaceProbe> probes;
  // Jittered within the cells: a view framed on the scene's edges (the fog
  // box's opening) would otherwise put a whole row of cell centres at the
  // same distance from an edge.
  PCG32 rng(0x5eed, 17);
  for (const Point2f& filmPos : filmGrid(scene, grid, &rng)) appendProbe(scene, filmPos, probes);
  return probes;
}

std::vector<double> nearestPhotonRadii(const std::vector<SurfacePhoton>& photons,
                                       const std::vector<SurfaceProbe>& probes, int k, double upper) {
  std::vector<double> radii;
  if (probes.empty() || k < 1) return radii;
  // Cells of a sixteenth of the bound: the search starts there and doubles.
  const float start = float(upper / 16.0);
  const SurfacePhotonMap map(photons, start);
  std::vector<uint32_t> found;
  std::vector<float> near;  // squared distances of the photons on the probe's side
  for (const SurfaceProbe& probe : probes) {
    double radius = upper;
    for (float r = start;; r = std::min(2.0f * r, float(upper))) {
      map.query(probe.p, r, found);
      near.clear();
      for (uint32_t i : found)
        if (dot(map.photons()[i].n, probe.n) > 0.0f) near.push_back(squaredLength(map.photons()[i].p - probe.p));
      if (int(near.size()) >= k) {
        std::nth_element(near.begin(), near.begin() + (k - 1), near.end());
        radius = std::sqrt(double(near[size_t(k - 1)]));
        break;
      }
      if (r >= float(upper)) break;
    }
    radii.push_back(radius);
  }
  return radii;
}

DerivedSurfaceRadius deriveSurfaceRadius(const Scene& scene, const std::vector<SurfacePhoton>& photons, double upper) {
  DerivedSurfaceRadius d;
  if (photons.empty() || !(upper > 0.0) || !std::isfinite(upper)) return d;
  const std::vector<SurfaceProbe> probes = surfaceProbes(scene);
  if (probes.empty()) return d;
  d.density = median(nearestPhotonRadii(photons, probes, SurfacePhotonsPerGather, upper));
  std::vector<double> footprints;
  for (const SurfaceProbe& probe : probes)
    if (probe.footprint > 0.0) footprints.push_back(PixelFootprints * probe.footprint);
  d.pixels = footprints.empty() ? upper : median(footprints);
  d.radius = std::min(d.density, d.pixels);
  return d;
}

}  // namespace femto::beams
