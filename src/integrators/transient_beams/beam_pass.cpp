#include <transient_beams/beam_pass.h>

namespace femto::beams {

BeamPass::BeamPass(const Scene& scene, const BeamSettings& settings, int pass, uint64_t seed, double horizon)
    : BeamPass(settings, pass, tracePhotonPass(scene, settings, seed, horizon)) {}

BeamPass::BeamPass(const BeamSettings& settings, int pass, PhotonPass traced)
    : settings_(settings),
      beams_(std::move(traced.beams), settings.beamRadius(pass)),
      photons_(std::move(traced.surfacePhotons), settings.surfaceRadiusOf(pass)),
      maps_{beams_, photons_, settings.beamRadius(pass), settings.surfaceRadiusOf(pass), traced.photonCount} {}

void BeamPass::sample(const Scene& scene, const Ray& ray, Sampler& sampler, RadianceRecorder& recorder) const {
  CameraTracer tracer(settings_, maps_, scratch_.local());
  tracer.sample(scene, ray, sampler, recorder);
}

std::string BeamPass::toString() const {
  return str("BeamPass[beams=", beams_.beams().size(), ", surface_photons=", photons_.size(),
             ", photons=", maps_.photonCount, ", radius=", maps_.beamRadius, ", surface_radius=", maps_.surfaceRadius,
             "]");
}

}  // namespace femto::beams
