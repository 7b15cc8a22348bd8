// Ambient occlusion: an out-of-tree femto integrator plugin.
//
// For the first surface a camera ray hits, estimates the cosine-weighted
// fraction of the hemisphere that is unoccluded within `max_distance`:
//
//   AO(x) = 1/pi * integral over the hemisphere of V(x, w) cos(theta) dw
//
// with cosine-weighted directions (pdf cos(theta)/pi), so each ray contributes
// its visibility (0 or 1) and the estimate is the mean over `samples` rays.
// Rays that leave the scene give 0 (no surface to shade).
//
// | parameter    | type    | default  | meaning                                          |
// |--------------|---------|----------|--------------------------------------------------|
// | samples      | integer | 4        | occlusion rays per camera sample                 |
// | max_distance | float   | infinity | occluders farther than this are ignored (scene units) |
#include <algorithm>

#include <femto/core/plugin.h>
#include <femto/math/frame.h>
#include <femto/math/warp.h>
#include <femto/render/integrator.h>
#include <femto/render/interaction.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>

namespace {

using namespace femto;

class AmbientOcclusion final : public SamplingIntegrator {
 public:
  explicit AmbientOcclusion(const Properties& props)
      : samples_(int(props.getInt("samples", 4, 1, 1 << 20))), maxDistance_(props.getFloat("max_distance", Infinity)) {
    if (!(maxDistance_ > 0)) props.raise("max_distance", str("max_distance must be positive, got ", maxDistance_));
  }

  Color3f Li(const Ray& ray, const Scene& scene, Sampler& sampler) const override {
    SurfaceInteraction si;
    if (!scene.rayIntersect(ray, si)) return Color3f(0.0f);
    // Occlusion is measured on the side the camera sees, whatever way the
    // surface's normal points.
    const Frame frame(faceForward(si.n, -ray.d));
    int unoccluded = 0;
    for (int i = 0; i < samples_; ++i) {
      Vec3f direction = frame.toWorld(warp::squareToCosineHemisphere(sampler.next2D()));
      Ray shadow = si.spawnRay(direction);
      shadow.tmax = std::min(shadow.tmax, maxDistance_);
      if (!scene.rayTest(shadow)) ++unoccluded;
    }
    return Color3f(float(unoccluded) / float(samples_));
  }

  std::string toString() const override {
    return str("ambient_occlusion[samples=", samples_, ", max_distance=", maxDistance_, "]");
  }

 private:
  int samples_;
  float maxDistance_;
};

}  // namespace

FEMTO_EXPORT_PLUGIN(AmbientOcclusion, Integrator, "ambient_occlusion",
                    "ambient occlusion: unoccluded fraction of the cosine-weighted hemisphere (example plugin)")
