#include <femto/transport/direct_lighting.h>

#include <cmath>

#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>
#include <femto/render/scene.h>

namespace femto {

float powerHeuristic(float nA, float pdfA, float nB, float pdfB) {
  float a = nA * pdfA, b = nB * pdfB;
  a *= a;
  b *= b;
  return a > 0.0f ? a / (a + b) : 0.0f;
}

float powerHeuristic(float pdfA, float pdfB, float pdfC) {
  // In double: the densities of equiangular vertices near a light reach 1e6 and more.
  double a = double(pdfA) * pdfA, b = double(pdfB) * pdfB, c = double(pdfC) * pdfC;
  return a > 0.0 ? float(a / (a + b + c)) : 0.0f;
}

Color3f sampleEmitterMIS(const Scene& scene, const SurfaceInteraction& si, const BSDF& bsdf, const Point2f& u,
                         const MISSampleCounts& counts) {
  if (!bsdf.hasSmooth()) return Color3f(0.0f);  // a delta BSDF never reflects a sampled direction
  DirectionSample ds;
  Color3f emitterWeight = scene.sampleEmitterDirection(si, u, ds, true);
  if (!(ds.pdf > 0.0f) || emitterWeight.isBlack()) return Color3f(0.0f);
  Vec3f wo = si.toLocal(ds.d);
  Color3f f = bsdf.eval(si, wo);
  if (f.isBlack()) return Color3f(0.0f);
  // BSDF sampling can never produce a direction toward a delta emitter.
  float weight = ds.delta ? 1.0f : powerHeuristic(counts.emitter, ds.pdf, counts.bsdf, bsdf.pdf(si, wo));
  return f * emitterWeight * weight;
}

Color3f emissionFound(const Scene& scene, const SurfaceInteraction& hit, const Vec3f& d, float distance,
                      const ScatterOrigin& from) {
  const Emitter* emitter = hit.emitter();
  if (!emitter) return Color3f(0.0f);
  Color3f Le = hit.Le(-d);
  if (Le.isBlack() || from.delta) return Le;
  DirectionSample ds;
  ds.p = hit.p;
  ds.n = hit.n;
  ds.d = d;
  ds.dist = distance;
  return Le * powerHeuristic(from.counts.bsdf, from.bsdfPdf, from.counts.emitter,
                             scene.pdfEmitterDirection(from.p, ds, emitter));
}

Color3f environmentFound(const Scene& scene, const Ray& ray, const ScatterOrigin& from, const Emitter* only) {
  Color3f result(0.0f);
  for (const Emitter* emitter : scene.environmentEmitters()) {
    if (only && emitter != only) continue;
    Color3f Le = emitter->evalEnvironment(ray);
    if (Le.isBlack()) continue;
    float weight = 1.0f;
    if (!from.delta) {
      DirectionSample ds;
      ds.d = ray.d;
      ds.dist = Infinity;
      ds.p = from.p + ray.d;  // only the direction matters for distant emitters
      weight = powerHeuristic(from.counts.bsdf, from.bsdfPdf, from.counts.emitter,
                              scene.pdfEmitterDirection(from.p, ds, emitter));
    }
    result += Le * weight;
  }
  return result;
}

}  // namespace femto
