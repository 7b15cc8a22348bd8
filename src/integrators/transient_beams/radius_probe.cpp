#include <transient_beams/radius_probe.h>

#include <cmath>

#include <femto/render/film.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/transport/optical_path.h>
#include <femto/transport/volumetric.h>
#include <transient_beams/medium_extent.h>

namespace femto::beams {

std::vector<ProbeSegment> probeSegments(const Scene& scene, double horizon, bool observerTime) {
  std::vector<ProbeSegment> probes;
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  const Point2i offset = film.cropOffset(), size = film.cropSize();
  for (int j = 0; j < ProbeGrid; ++j)
    for (int i = 0; i < ProbeGrid; ++i) {
      const Point2f filmPos(float(offset.x) + float(size.x) * (float(i) + 0.5f) / ProbeGrid,
                            float(offset.y) + float(size.y) * (float(j) + 0.5f) / ProbeGrid);
      Ray ray;
      if (sensor.sampleRay(filmPos, Point2f(0.5f, 0.5f), ray).isBlack()) continue;
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
  return probes;
}

}  // namespace femto::beams
