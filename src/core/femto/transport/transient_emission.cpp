#include <femto/transport/transient_emission.h>

#include <femto/render/emitter.h>
#include <femto/render/scene.h>
#include <femto/render/transient_integrator.h>
#include <femto/transport/direct_lighting.h>

namespace femto {

void recordEnvironmentEmission(const Scene& scene, const Ray& ray, const ScatterOrigin& from, double opl,
                               const Color3f& throughput, RadianceRecorder& recorder) {
  for (const Emitter* emitter : scene.environmentEmitters()) {
    Color3f Le = environmentFound(scene, ray, from, emitter);
    if (!Le.isBlack()) recorder.addPulsed(opl, opl, throughput * Le, emitter->pulse());
  }
}

void recordSurfaceEmission(const Scene& scene, const SurfaceInteraction& si, const Vec3f& d, float distance,
                           const ScatterOrigin& from, double opl, const Color3f& throughput,
                           RadianceRecorder& recorder) {
  if (!si.emitter()) return;
  Color3f Le = emissionFound(scene, si, d, distance, from);
  if (!Le.isBlack()) recorder.addPulsed(opl, opl, throughput * Le, si.emitter()->pulse());
}

}  // namespace femto
