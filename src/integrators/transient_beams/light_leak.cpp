// The kernel's leak around a point light (light_leak.h, docs/design/photon-beams.md).
#include <transient_beams/light_leak.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>
#include <femto/render/emitter.h>
#include <femto/render/medium.h>
#include <femto/render/scene.h>

namespace femto::beams {

double lightLeak(double x) {
  // lambda(x) = 2 pi int_x^inf g(u) u (u - x) du with g = 2 - 1 / u^2 (u < 1) and
  // g = 2 - 2 sqrt(1 - 1 / u^2) - 1 / u^2 (u >= 1); antiderivatives of the
  // second: A(u) = 2u^3/3 - (2/3)(u^2 - 1)^(3/2) - u (A(inf) = 0) for
  // g u^2, B(u) = u^2 - u sqrt(u^2 - 1) + ln(u + sqrt(u^2 - 1)) - ln u
  // (B(inf) = 1/2 + ln 2) for g u; A(1) = -1/3, B(1) = 1.
  if (!(x > 0.0)) return 0.0;
  const double ln2 = std::log(2.0);
  if (x < 1.0) return 2.0 * Pi * (x * x * x / 3.0 - x * std::log(x) - x * (ln2 - 0.5));
  // Far: the tail g ~ 1 / (4 u^4) gives pi / (4 x); the closed form below
  // cancels x^3 terms, so beyond x = 100 (where they agree to 1e-5) the tail.
  if (x > 100.0) return Pi / (4.0 * x);
  const double s = std::sqrt(x * x - 1.0);
  const double a = 2.0 * x * x * x / 3.0 - 2.0 / 3.0 * s * s * s - x;
  const double b = x * x - x * s + std::log(x + s) - std::log(x);
  return 2.0 * Pi * (-a - x * (0.5 + ln2 - b));
}

double lightBiasOf(double radius, double gap, double depth) {
  // lambda's envelope from above, its peak nearer than x = 0.34: a light on
  // the boundary leaks little only because the plane halves its blur, and
  // the gap is measured on discrete rays and beams.
  return OneDLeakFactor * radius * lightLeak(std::max(gap / radius, LeakPeak)) / (Pi * depth);
}

double lightRadius(double gap, double depth) {
  if (!(gap > 0.0) || !(gap < Infinity) || !(depth > 0.0) || !(depth < Infinity)) return Infinity;
  // r lambda(gap / r) = gap lambda(x) / x grows as x = gap / r falls
  // (lambda(x) / x decreases): bisect log r.
  double lo = gap * 1e-6, hi = gap * 1e6;
  if (lightBiasOf(hi, gap, depth) <= LightBiasTarget) return Infinity;
  for (int i = 0; i < 100; ++i) {
    const double mid = std::sqrt(lo * hi);
    (lightBiasOf(mid, gap, depth) <= LightBiasTarget ? lo : hi) = mid;
  }
  return lo;
}

double lightBoundRadius(const Scene& scene, const std::vector<Beam>& beams, const std::vector<ProbeSegment>& probes,
                        const std::vector<ProbeSegment>& edges) {
  double radius = Infinity;
  const auto& emitters = scene.emitters();
  for (size_t e = 0; e < emitters.size(); ++e) {
    Point3f light;
    const Medium* medium = emitters[e]->medium();
    if (!medium || !emitters[e]->deltaPosition(light)) continue;
    // Nothing gathered in its medium: no bias to bound.
    double length = 0.0;
    int count = 0;
    for (const ProbeSegment& p : probes)
      if (p.medium == medium) length += double(p.segment.tMax), ++count;
    if (count == 0) continue;
    const float sigmaT = medium->majorant().maxValue();
    const double depth = std::min(sigmaT > 0.0f ? 1.0 / double(sigmaT) : Infinity, length / count);
    // The view's edge: how near the rays through the film's border pass.
    double gap = Infinity;
    for (const ProbeSegment& p : edges)
      if (p.medium == medium)
        gap = std::min(gap, segmentDistance(light, Vec3f(0.0f, 0.0f, 1.0f), 0.0f, p.segment.ray.o, p.segment.ray.d,
                                            p.segment.tMax));
    // The medium's boundary: the shortest first segment from the light that
    // ends on one (beams from the light in every direction; extended ones).
    for (const Beam& b : beams)
      if (b.emitter == e && b.depth == 1 && b.medium == medium && b.after > 0.0f) gap = std::min(gap, double(b.length));
    radius = std::min(radius, lightRadius(gap, depth));
  }
  return radius;
}

}  // namespace femto::beams
