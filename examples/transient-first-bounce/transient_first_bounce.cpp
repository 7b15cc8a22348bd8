// transient_first_bounce: an out-of-tree transient integrator (example plugin).
//
// Follows each camera ray to the first surface it hits that is not an
// index-matched medium boundary; media on the way only attenuate it (their
// transmittance: light they scatter is left out). There it records
//
//   mode = "direct": the surface's emission, and one next-event estimate of
//     direct light f * Le * T / pdf (emitter sampling alone: nothing else
//     finds the light, so no MIS is needed), at the OPL camera -> x -> light,
//     with the emitter's pulse (RadianceRecorder::addPulsed);
//   mode = "depth": a time-of-flight depth camera: weight 1 at the OPL of the
//     camera segment alone. Each pixel's transient holds the distances it
//     sees; the steady image is 1 wherever a surface is hit.
//
// "direct" is the first-bounce term of the transient rendering equation
// (Marco et al., "Transient Photon Beams", eq. 1-3). docs/plugins.md,
// "Writing a transient integrator", walks through this file.
//
// | parameter | type   | default  | meaning                                  |
// |-----------|--------|----------|------------------------------------------|
// | mode      | string | "direct" | "direct" (first bounce) or "depth" (ToF) |
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>
#include <femto/render/medium.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/transient_integrator.h>
#include <femto/transport/direct_lighting.h>
#include <femto/transport/optical_path.h>
#include <femto/transport/transient_emission.h>
#include <femto/transport/volumetric.h>

namespace {

using namespace femto;

class TransientFirstBounce final : public TransientIntegrator {
 public:
  enum class Mode { Direct, Depth };

  explicit TransientFirstBounce(const Properties& props)
      : mode_(props.getEnum("mode", Mode::Direct, {{"direct", Mode::Direct}, {"depth", Mode::Depth}})) {}

  void sample(const Scene& scene, const Ray& cameraRay, Sampler& sampler, RadianceRecorder& recorder) const override {
    OpticalPath path;  // where the ray is and its OPL there (0 at the sensor)
    path.ray = cameraRay;
    path.vertex = cameraRay.o;
    path.medium = scene.sensor().medium();
    ScatterOrigin camera;  // a camera ray: emission it finds needs no MIS weight
    camera.p = cameraRay.o;
    Color3f throughput(1.0f);  // transmittance of the media crossed so far
    for (int crossed = 0; crossed < MaxPassThrough; ++crossed) {
      SurfaceInteraction si;
      const bool hit = scene.rayIntersect(path.ray, si);
      if (path.medium && mode_ == Mode::Direct)
        throughput *= path.medium->transmittance(path.ray, hit ? si.t : Infinity, sampler);
      if (!hit) {
        if (mode_ == Mode::Direct)
          recordEnvironmentEmission(scene, path.ray, camera, path.opl, throughput, recorder);
        return;
      }
      // Stop once the OPL passes the horizon: nothing later reaches the film.
      if (throughput.isBlack() || !path.advance(si.p) || path.opl >= recorder.horizon()) return;
      if (isPassThrough(si)) {  // a medium's boundary: continue straight on, maybe into another medium
        path.crossBoundary(si);
        continue;
      }
      if (mode_ == Mode::Depth) {
        recorder.add(path.opl, Color3f(1.0f));
        return;
      }
      recordSurfaceEmission(scene, si, path.ray.d, distance(camera.p, si.p), camera, path.opl, throughput, recorder);
      directLight(scene, path, si, throughput, sampler, recorder);
      return;
    }
  }

  std::string toString() const override {
    return str("TransientFirstBounce[mode=", mode_ == Mode::Direct ? "direct" : "depth", "]");
  }

 private:
  /// One next-event estimate at surface `si`, reached along `path` with `throughput`.
  static void directLight(const Scene& scene, const OpticalPath& path, const SurfaceInteraction& si,
                          const Color3f& throughput, Sampler& sampler, RadianceRecorder& recorder) {
    const BSDF& bsdf = *si.bsdf();
    if (!bsdf.hasSmooth()) return;  // mirrors and glass: a point sample never meets their delta lobe
    double opl = path.opl;
    if (bsdf.hasDelay()) opl += bsdf.sampleDelay(sampler.next1D());  // time spent scattering here
    DirectionSample ds;
    const Color3f emitterWeight = scene.sampleEmitterDirection(si, sampler.next2D(), ds, /*testVisibility=*/false);
    if (!(ds.pdf > 0.0f) || emitterWeight.isBlack()) return;
    // The light segment adds at least its length (eta >= 1): skip what cannot arrive in time.
    if (std::isfinite(ds.dist) && opl + ds.dist >= recorder.horizon()) return;
    const Color3f f = bsdf.eval(si, si.toLocal(ds.d));  // f * |cos|
    if (f.isBlack()) return;
    // Shadow ray through media and their boundaries: transmittance and the segment's OPL.
    const Connection c =
        connect(scene, si, ds.d, ds.p, ds.dist, mediumAfter(si, ds.d, path.medium), path.surfaceEta, sampler);
    if (c.transmittance.isBlack()) return;
    // Computed for a Dirac emission at OPL 0: the film convolves it with the emitter's pulse.
    const double arrival = opl + c.opl;
    recorder.addPulsed(arrival, arrival, throughput * f * emitterWeight * c.transmittance, ds.emitter->pulse());
  }

  Mode mode_;
};

}  // namespace

FEMTO_EXPORT_PLUGIN(TransientFirstBounce, Integrator, "transient_first_bounce",
                    "first bounce with direct light, or ToF depth, at each pixel's optical path length (example plugin)")
