#include <transient_beams/beam_pass.h>

namespace femto::beams {
namespace {

/// The beam map's pieces: up to 16 per beam rather than the map's default 4.
/// A pass's beams are few (beam_photon_count) and its radius small, so long
/// beams cut into 4 pieces have boxes far wider than their capsules: on the
/// fog Cornell box (3000 beam photons, r = 0.004) 16 pieces return 3x fewer
/// candidates per camera segment and halve the camera pass's time, at 4x the
/// (small) map.
BeamMapOptions mapOptions() {
  BeamMapOptions options;
  options.maxPiecesPerBeam = 16.0f;
  return options;
}

}  // namespace

BeamPass::BeamPass(const Scene& scene, const BeamSettings& settings, int pass, uint64_t seed, double horizon)
    : BeamPass(settings, pass, tracePhotonPass(scene, settings, seed, horizon)) {}

BeamPass::BeamPass(const BeamSettings& settings, int pass, PhotonPass traced)
    : buildStart_(std::chrono::steady_clock::now()),
      settings_(settings),
      beams_(std::move(traced.beams), settings.beamRadius(pass), mapOptions()),
      photons_(std::move(traced.surfacePhotons), settings.surfaceRadiusOf(pass)),
      maps_{beams_,
            photons_,
            settings.beamRadius(pass),
            settings.surfaceRadiusOf(pass),
            traced.photonCount,
            traced.beamPhotonCount > 0 ? traced.beamPhotonCount : traced.photonCount},
      traceSeconds_(traced.traceSeconds) {
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart_).count();
}

void BeamPass::sample(const Scene& scene, const Ray& ray, Sampler& sampler, RadianceRecorder& recorder) const {
  CameraTracer tracer(settings_, maps_, threads_.local());
  tracer.sample(scene, ray, sampler, recorder);
}

CameraStatistics BeamPass::cameraStatistics() const {
  CameraStatistics total;
  for (const CameraScratch& t : threads_) total += t.stats;
  return total;
}

std::string BeamPass::toString() const {
  return str("BeamPass[beams=", beams_.beams().size(), ", surface_photons=", photons_.size(),
             ", photons=", maps_.photonCount, ", beam_photons=", maps_.beamPhotonCount, ", radius=", maps_.beamRadius, ", surface_radius=", maps_.surfaceRadius,
             "]");
}

}  // namespace femto::beams
