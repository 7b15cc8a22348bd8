// path: unidirectional path tracing with next-event estimation. At every
// non-delta vertex it samples an emitter and the BSDF and combines both with
// multiple importance sampling (power heuristic, Veach 1997, sec. 9.2.4);
// paths are ended by Russian roulette on the throughput.
//
// Depth counts path segments, as in Mitsuba: max_depth = 1 gives only
// emitters seen directly, 2 adds direct illumination, -1 is unbounded.
//
// | name          | type    | default | meaning                                           | unit |
// |---------------|---------|---------|---------------------------------------------------|------|
// | max_depth     | integer | -1      | longest path in segments (-1: no limit)           | -    |
// | rr_depth      | integer | 5       | depth from which Russian roulette may end paths   | -    |
// (max_depth and rr_depth: PathDepthSettings, render/path_depth.h)
// | hide_emitters | boolean | false   | emitters seen directly by the camera appear black | -    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/transport/direct_lighting.h>
#include <femto/render/integrator.h>
#include <femto/render/path_depth.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/transport/volumetric.h>

namespace femto {

class PathIntegrator final : public SamplingIntegrator {
 public:
  explicit PathIntegrator(const Properties& props)
      : depth_(PathDepthSettings::read(props)), hideEmitters_(props.getBool("hide_emitters", false)) {}

  RenderStats render(const Scene& scene, const RenderOptions& options) const override {
    warnIfMediaIgnored(scene, "path");
    return SamplingIntegrator::render(scene, options);
  }

  Color3f Li(const Ray& cameraRay, const Scene& scene, Sampler& sampler) const override {
    Color3f L(0.0f), throughput(1.0f);
    if (depth_.maxDepth == 0) return L;
    Ray ray = cameraRay;
    // The previous scattering vertex, for weighting emission found by BSDF
    // sampling; camera rays count as delta: no other strategy finds what they see.
    ScatterOrigin prev;
    prev.p = ray.o;
    float travelled = 0.0f;  // along ray.d since prev.p, across interfaces the path passed straight through
    float etaScale = 1.0f;
    for (int depth = 0;; ) {
      SurfaceInteraction si;
      if (!scene.rayIntersect(ray, si)) {
        if (!(hideEmitters_ && depth == 0)) L += throughput * environmentFound(scene, ray, prev);
        break;
      }
      // Emission found by the path (a camera ray, or BSDF sampling).
      if (!(hideEmitters_ && depth == 0)) L += throughput * emissionFound(scene, si, ray.d, travelled + si.t, prev);

      if (++depth == depth_.maxDepth) break;  // the next segment would exceed max_depth
      const BSDF* bsdf = si.bsdf();
      if (!bsdf) {  // an interface that only bounds media: continue straight on
        travelled += si.t;
        ray = si.spawnRay(ray.d);
        --depth;
        continue;
      }

      // Next-event estimation: a path one segment longer, ending on an emitter.
      L += throughput * sampleEmitterMIS(scene, si, *bsdf, sampler.next2D());

      // BSDF sampling: continue the path.
      BSDFSample bs;
      Color3f bsdfWeight = bsdf->sample(si, sampler.next1D(), sampler.next2D(), bs);
      if (!(bs.pdf > 0.0f) || bsdfWeight.isBlack()) break;
      throughput *= bsdfWeight;
      etaScale *= bs.eta * bs.eta;
      prev.p = si.p;
      travelled = 0.0f;
      prev.bsdfPdf = bs.pdf;
      prev.delta = (bs.sampledFlags & BSDFFlags::Delta) != 0;
      ray = si.spawnRay(si.toWorld(bs.wo));

      // Russian roulette on the throughput, with the radiance scaling of
      // refraction removed so paths inside glass are not killed unfairly
      // (as Mitsuba 3's path integrator).
      if (depth >= depth_.rrDepth) {
        float q = std::min(throughput.maxValue() * etaScale, 0.95f);
        if (!(sampler.next1D() < q)) break;
        throughput = throughput / q;
      }
    }
    return L;
  }

  std::string toString() const override {
    return str("PathIntegrator[", depth_.toString(), ", hide_emitters=", hideEmitters_ ? "true" : "false", "]");
  }

 private:
  PathDepthSettings depth_;
  bool hideEmitters_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::PathIntegrator, Integrator, "path", "Unidirectional path tracer with MIS")
