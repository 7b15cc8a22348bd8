#include <transient_beams/radius_probe.h>

#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/render/film.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/transport/optical_path.h>
#include <femto/transport/volumetric.h>
#include <transient_beams/medium_extent.h>

namespace femto::beams {

namespace {

/// The camera ray through `filmPos` (aperture centre), followed straight
/// through index-matched boundaries, its pieces inside media appended.
void appendProbes(const Scene& scene, const Point2f& filmPos, double horizon, bool observerTime,
                  std::vector<ProbeSegment>& probes) {
  const Sensor& sensor = scene.sensor();
  Ray ray;
  if (sensor.sampleRay(filmPos, Point2f(0.5f, 0.5f), ray).isBlack()) return;
  OpticalPath path;
  path.ray = Ray(ray.o, ray.d);
  path.vertex = ray.o;
  path.medium = sensor.medium();
  for (int crossing = 0; crossing < MaxPassThrough; ++crossing) {
    SurfaceInteraction si;
    const bool hit = scene.rayIntersect(path.ray, si);
    if (path.medium) {
      // As the camera tracer's segments (observer time off: no horizon on the first).
      const float tMax = hit ? distance(path.vertex, si.p)
                             : unboundedSegmentLength(*path.medium, path.opl, observerTime ? horizon : Infinity);
      if (tMax > 0.0f && std::isfinite(tMax)) {
        ProbeSegment& p = probes.emplace_back();
        p.segment.ray = Ray(path.vertex, path.ray.d);
        p.segment.tMax = tMax;
        p.segment.eta = observerTime ? path.medium->eta() : 0.0f;
        p.medium = path.medium;
      }
    }
    if (!hit || !path.advance(si.p, observerTime) || path.opl >= horizon || !isPassThrough(si)) break;
    path.crossBoundary(si);
  }
}

}  // namespace

std::vector<Point2f> filmGrid(const Scene& scene, int grid, PCG32* jitter) {
  std::vector<Point2f> positions;
  const Film& film = scene.sensor().film();
  const Point2i offset = film.cropOffset(), size = film.cropSize();
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const float u = jitter ? jitter->nextFloat() : 0.5f, v = jitter ? jitter->nextFloat() : 0.5f;
      positions.emplace_back(float(offset.x) + float(size.x) * (float(i) + u) / float(grid),
                             float(offset.y) + float(size.y) * (float(j) + v) / float(grid));
    }
  return positions;
}

std::vector<ProbeSegment> probeSegments(const Scene& scene, double horizon, bool observerTime, int grid) {
  std::vector<ProbeSegment> probes;
  for (const Point2f& filmPos : filmGrid(scene, grid)) appendProbes(scene, filmPos, horizon, observerTime, probes);
  return probes;
}

std::vector<ProbeSegment> edgeProbeSegments(const Scene& scene, double horizon, bool observerTime) {
  std::vector<ProbeSegment> probes;
  const Film& film = scene.sensor().film();
  const float x0 = float(film.cropOffset().x), y0 = float(film.cropOffset().y);
  const float w = float(film.cropSize().x), h = float(film.cropSize().y);
  for (int k = 0; k <= EdgeProbes; ++k) {
    const float u = float(k) / EdgeProbes;
    for (const Point2f& p :
         {Point2f(x0 + u * w, y0), Point2f(x0 + u * w, y0 + h), Point2f(x0, y0 + u * h), Point2f(x0 + w, y0 + u * h)})
      appendProbes(scene, p, horizon, observerTime, probes);
  }
  return probes;
}

}  // namespace femto::beams
