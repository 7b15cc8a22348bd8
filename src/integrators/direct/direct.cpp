// direct: direct illumination only (Mitsuba's `direct`). The radiance seen
// along a camera ray is the emission of the surface it hits plus light that
// reaches that surface straight from an emitter and reflects once: a path
// tracer with max_depth 2. The reflected part is estimated with
// `emitter_samples` emitter samples and `bsdf_samples` BSDF samples, combined
// by multiple importance sampling (power heuristic over the
// sample-count-scaled densities, Veach 1997, sec. 9.2.4), as Mitsuba does.
// Shapes without a BSDF (index-matched media boundaries) are passed straight
// through.
//
// | name            | type    | default         | meaning                                              |
// |-----------------|---------|-----------------|------------------------------------------------------|
// | shading_samples | integer | 1               | default of both emitter_samples and bsdf_samples     |
// | emitter_samples | integer | shading_samples | emitter (next-event) samples per camera sample       |
// | bsdf_samples    | integer | shading_samples | BSDF samples per camera sample                       |
// | hide_emitters   | boolean | false           | emitters seen directly by the camera appear black    |
#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/transport/direct_lighting.h>
#include <femto/render/integrator.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/transport/volumetric.h>

namespace femto {

class DirectIntegrator final : public SamplingIntegrator {
 public:
  explicit DirectIntegrator(const Properties& props) {
    int shading = readCount(props, "shading_samples", 1);
    emitterSamples_ = readCount(props, "emitter_samples", shading);
    bsdfSamples_ = readCount(props, "bsdf_samples", shading);
    if (emitterSamples_ + bsdfSamples_ == 0)
      props.raise(props.has("bsdf_samples") ? "bsdf_samples" : "emitter_samples",
                  "emitter_samples and bsdf_samples cannot both be 0");
    hideEmitters_ = props.getBool("hide_emitters", false);
  }

  RenderStats render(const Scene& scene, const RenderOptions& options) const override {
    warnIfMediaIgnored(scene, "direct");
    return SamplingIntegrator::render(scene, options);
  }

  Color3f Li(const Ray& cameraRay, const Scene& scene, Sampler& sampler) const override {
    SurfaceInteraction si;
    float distance = 0.0f;
    if (!intersectSkippingInterfaces(scene, cameraRay, si, distance)) {
      return hideEmitters_ ? Color3f(0.0f) : environmentFound(scene, cameraRay, ScatterOrigin{});
    }
    // The camera ray is a delta "sample": emission it sees has weight 1.
    Color3f L = hideEmitters_ ? Color3f(0.0f) : emissionFound(scene, si, cameraRay.d, distance, ScatterOrigin{});
    const BSDF* bsdf = si.bsdf();
    if (!bsdf) return L;

    const MISSampleCounts counts{float(emitterSamples_), float(bsdfSamples_)};
    for (int i = 0; i < emitterSamples_; ++i)
      L += sampleEmitterMIS(scene, si, *bsdf, sampler.next2D(), counts) / float(emitterSamples_);

    for (int i = 0; i < bsdfSamples_; ++i) {
      BSDFSample bs;
      Color3f weight = bsdf->sample(si, sampler.next1D(), sampler.next2D(), bs);
      if (!(bs.pdf > 0.0f) || weight.isBlack()) continue;
      ScatterOrigin from;
      from.p = si.p;
      from.bsdfPdf = bs.pdf;
      from.delta = (bs.sampledFlags & BSDFFlags::Delta) != 0;
      from.counts = counts;
      Ray ray = si.spawnRay(si.toWorld(bs.wo));
      SurfaceInteraction hit;
      float hitDistance = 0.0f;
      Color3f Le = intersectSkippingInterfaces(scene, ray, hit, hitDistance)
                       ? emissionFound(scene, hit, ray.d, hitDistance, from)
                       : environmentFound(scene, ray, from);
      L += weight * Le / float(bsdfSamples_);
    }
    return L;
  }

  std::string toString() const override {
    return str("DirectIntegrator[emitter_samples=", emitterSamples_, ", bsdf_samples=", bsdfSamples_,
               ", hide_emitters=", hideEmitters_ ? "true" : "false", "]");
  }

 private:
  static int readCount(const Properties& props, const std::string& name, int def) {
    return int(props.getInt(name, def, 0, 1 << 16));
  }

  /// Nearest hit that scatters or emits, passing through shapes that only
  /// bound media; `distance` is measured from ray.o across them.
  static bool intersectSkippingInterfaces(const Scene& scene, Ray ray, SurfaceInteraction& si, float& distance) {
    distance = 0.0f;
    for (int crossings = 0; crossings < MaxPassThrough; ++crossings) {
      if (!scene.rayIntersect(ray, si)) return false;
      distance += si.t;
      if (si.bsdf() || si.emitter()) return true;
      ray = si.spawnRay(ray.d);
    }
    return false;  // a pathological stack of coincident interfaces: treat as escaped
  }

  int emitterSamples_ = 1, bsdfSamples_ = 1;
  bool hideEmitters_ = false;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::DirectIntegrator, Integrator, "direct", "Direct illumination with MIS")
