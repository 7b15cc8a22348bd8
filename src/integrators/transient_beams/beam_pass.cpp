#include <transient_beams/beam_pass.h>

#include <femto/render/film.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <transient_beams/radius_probe.h>

namespace femto::beams {
namespace {

/// The beam map's options: at most 16 pieces per beam on average rather than
/// the map's default 4 (the memory bound; a pass's beams are few). With a
/// scene the piece lengths follow the map's cost rule (beam_map.cpp, "Piece
/// length"): the crossings to expect are counted on the probe segments
/// (radius_probe.h, camera rays through an 8 x 8 grid of film positions),
/// each probe ray standing for 1/64 of the pass's camera samples (times the
/// gather fraction). On issue 14's box with light outside (r = 0.0049, beams
/// 270 r long) the fixed 4-radius pieces, 16 per beam under the cap, cost the
/// build 0.22 s against 0.26 s of camera queries (4 passes, 1 thread); the
/// rule's ~4 pieces per beam 0.06 s against 0.29 s. Without a scene: the
/// fixed pieces.
BeamMapOptions mapOptions(const std::vector<Beam>& beams, float radius, const Scene* scene, double horizon,
                          const BeamSettings& settings) {
  BeamMapOptions options;
  options.maxPiecesPerBeam = 16.0f;
  if (scene && !beams.empty()) {
    std::vector<CameraSegment> segments;
    for (const ProbeSegment& p : probeSegments(*scene, horizon, settings.observerTime)) segments.push_back(p.segment);
    const Film& film = scene->sensor().film();
    const double samples = double(film.cropSize().x) * double(film.cropSize().y) *
                           double(scene->sensor().sampler().sampleCount()) * double(settings.gathers());
    options.crossingDensity = BeamMap::crossingDensity(beams, radius, segments, samples / (ProbeGrid * ProbeGrid));
  }
  return options;
}

/// The pass's beam map, its options read off the beams before they move in.
BeamMap passBeamMap(std::vector<Beam>&& beams, float radius, const Scene* scene, double horizon,
                    const BeamSettings& settings) {
  const BeamMapOptions options = mapOptions(beams, radius, scene, horizon, settings);
  return BeamMap(std::move(beams), radius, options);
}

}  // namespace

BeamPass::BeamPass(const Scene& scene, const BeamSettings& settings, int pass, uint64_t seed, double horizon)
    : BeamPass(settings, pass, tracePhotonPass(scene, settings, seed, horizon), &scene, horizon) {}

BeamPass::BeamPass(const BeamSettings& settings, int pass, PhotonPass traced, const Scene* scene, double horizon)
    : buildStart_(std::chrono::steady_clock::now()),
      settings_(settings),
      beams_(passBeamMap(std::move(traced.beams), settings.beamRadius(pass), scene, horizon, settings)),
      photons_(std::move(traced.surfacePhotons), settings.surfaceRadiusOf(pass)),
      maps_{beams_,
            photons_,
            settings.beamRadius(pass),
            settings.surfaceRadiusOf(pass),
            settings.surfaceTimeWidthOf(pass),
            traced.photonCount,
            traced.beamPhotonCount > 0 ? traced.beamPhotonCount : traced.photonCount},
      traceSeconds_(traced.traceSeconds),
      tracedPhotons_(traced.tracedPhotons) {
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
             ", photons=", maps_.photonCount, ", beam_photons=", maps_.beamPhotonCount, ", radius=", maps_.beamRadius,
             ", surface_radius=", maps_.surfaceRadius, ", surface_time_width=", maps_.surfaceTimeWidth, "]");
}

}  // namespace femto::beams
