#include <transient_beams/surface_coverage.h>

#include <algorithm>
#include <cmath>

#include <femto/math/constants.h>
#include <femto/math/frame.h>
#include <femto/math/ray.h>
#include <femto/render/bsdf.h>
#include <femto/render/interaction.h>
#include <femto/render/scene.h>
#include <femto/render/shape.h>
#include <femto/transport/volumetric.h>

namespace femto::beams {

namespace {

/// Does `ray` (within its tmax) meet a surface that is not an index-matched
/// boundary (a medium's boundary is not an edge)?
bool hitsSolid(const Scene& scene, Ray ray) {
  if (!scene.hasPassThroughShapes()) return scene.rayTest(ray);
  // Preliminary hits: the interaction (shading frame, uv) is not needed,
  // and building it was a third of these casts' cost on the fog box.
  for (int crossing = 0; crossing < MaxPassThrough; ++crossing) {
    PreliminaryHit hit;
    if (!scene.rayIntersectPreliminary(ray, hit)) return false;
    if (!isPassThrough(hit.shape->bsdf())) return true;
    // On along the same ray, past the boundary (a relative step clears the hit's rounding).
    ray.tmin = hit.t + std::max(1e-5f * hit.t, 1e-7f);
    if (!(ray.tmin < ray.tmax)) return false;
  }
  return false;
}

}  // namespace

double coveredShare(const Scene& scene, const Point3f& p, const Vec3f& n, double r) {
  if (!(r > 0.0)) return 1.0;
  const Frame frame(n);
  const float lift = float(0.1 * r), rho = float(2.0 * r / 3.0);  // CoveragePoints
  const Point3f from = p + n * lift;
  int covered = 0;
  for (int k = 0; k < CoveragePoints; ++k) {
    const double phi = 2.0 * Pi * (double(k) + 0.5) / CoveragePoints;
    const Vec3f across = frame.s * float(std::cos(phi)) + frame.t * float(std::sin(phi));
    if (hitsSolid(scene, Ray(from, across, 0.0f, rho))) continue;  // a wall in the way
    covered += hitsSolid(scene, Ray(from + across * rho, -n, 0.0f, lift + float(1.5 * r)));
  }
  return double(covered) / CoveragePoints;
}

}  // namespace femto::beams
