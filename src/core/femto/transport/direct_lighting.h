#pragma once
// Direct illumination shared by the integrators: next-event estimation (one
// emitter sample at a surface point) and the weighting of emission that BSDF
// sampling finds, combined by multiple importance sampling with the power
// heuristic (Veach 1997, sec. 9.2.4). Both strategies may take several
// samples (the `direct` integrator's emitter_samples/bsdf_samples): the
// weights then use the sample-count-scaled densities n_i p_i (Veach's
// multi-sample model, eq. 9.13), and the caller divides each strategy's sum
// by its own sample count.
#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto {

class BSDF;
class Emitter;
class Scene;
struct Ray;
struct SurfaceInteraction;

/// Power heuristic with beta = 2 (Veach 1997, eq. 9.13): the weight of a
/// sample of strategy A with `nA` samples of density `pdfA` against strategy
/// B with `nB` samples of density `pdfB`. Zero when A has zero density.
float powerHeuristic(float nA, float pdfA, float nB, float pdfB);
/// The same for one sample of each of three strategies: the weight of the one
/// of density `pdfA` against those of densities `pdfB` and `pdfC`.
float powerHeuristic(float pdfA, float pdfB, float pdfC);

/// How many samples each strategy takes (both 1 in a path tracer).
struct MISSampleCounts {
  float emitter = 1.0f;
  float bsdf = 1.0f;
};

/// The scattering vertex a ray left by BSDF sampling, for weighting the
/// emission that ray finds against emitter sampling from the same vertex.
struct ScatterOrigin {
  Point3f p;            // the vertex
  float bsdfPdf = 1.0f; // solid-angle density of the sampled direction
  bool delta = true;    // sampled from a delta component (or a camera ray): no other strategy competes
  MISSampleCounts counts;
};

/// One next-event estimate at `si` (with its BSDF): samples an emitter with
/// `u`, tests visibility and returns f * Le * |cos| / pdf toward si.wi,
/// MIS-weighted against BSDF sampling (weight 1 for delta emitters). Black
/// when the BSDF has no smooth component or nothing is visible.
Color3f sampleEmitterMIS(const Scene& scene, const SurfaceInteraction& si, const BSDF& bsdf, const Point2f& u,
                         const MISSampleCounts& counts = {});

/// Radiance emitted by surface `hit` back along `d` (the direction the ray
/// travelled), which lies `distance` from `from.p`, MIS-weighted against
/// emitter sampling from `from`. Black when `hit` is not on an emitter.
Color3f emissionFound(const Scene& scene, const SurfaceInteraction& hit, const Vec3f& d, float distance,
                      const ScatterOrigin& from);

/// Radiance of the environment emitters along a ray that escaped the scene,
/// each MIS-weighted against emitter sampling from `from`; only that of
/// `only` when given (transient integrators record each emitter with its pulse).
Color3f environmentFound(const Scene& scene, const Ray& ray, const ScatterOrigin& from, const Emitter* only = nullptr);

}  // namespace femto
