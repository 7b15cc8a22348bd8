#include <transient_beams/beam_settings.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <femto/math/constants.h>
#include <transient_beams/boundary_coverage.h>

namespace femto::beams {
namespace {

/// Default radii as fractions of the scene's bounding-box diagonal: small
/// enough that the kernel blur stays below a pixel's footprint in typical
/// views, large enough for ~1e5 photons to give a usable first pass. The
/// beam radius uses them only when nothing else bounds it (withBeamRadiusFrom).
constexpr float BeamRadiusFraction = 0.005f, SurfaceRadiusFraction = 0.01f;
/// Upper bound of the beams' spread radius, as a fraction of the diagonal.
constexpr float MaxBeamRadiusFraction = 0.01f;

/// Product over passes 0..pass-1 of (i + alpha) / (i + 1).
double reduction(float alpha, int pass) {
  double f = 1.0;
  for (int i = 0; i < pass; ++i) f *= (double(i) + alpha) / double(i + 1);
  return f;
}

}  // namespace

BeamSettings BeamSettings::parse(const Properties& props) {
  BeamSettings s;
  s.location = props.location();
  constexpr int64_t MaxPhotons = int64_t(1) << 32;
  s.passes = int(props.getInt("passes", 1, 1, 1000000));
  s.photonCount = props.getInt("photon_count", s.photonCount, 1, MaxPhotons, "photons per pass");
  // Beams cost far more per photon than surface photons (a BVH over beam
  // pieces, queried by every camera segment), and an evenly lit medium needs
  // fewer of them: by default only the first 10000 photons leave beams.
  s.beamPhotonCountGiven = props.has("beam_photon_count");
  s.beamPhotonCount = props.getInt("beam_photon_count", s.beamPhotonCount, 0, MaxPhotons, "0: all photons leave beams");
  // 0 (as when absent) asks for the default derived from the scene (resolved()).
  const char* radiusNote = "a radius in scene units; 0: derived from the scene";
  s.radius = props.getFloat("radius", 0.0f, Range::nonNegative(), radiusNote);
  s.surfaceRadius = props.getFloat("surface_radius", 0.0f, Range::nonNegative(), radiusNote);
  s.surfaceRadiusFinal = s.surfaceRadius > 0.0f;
  if (props.has("surface_time_width"))
    s.surfaceTimeWidth = props.getFloat("surface_time_width", 0.0f, Range::nonNegative(),
                                        "an OPL width; 0: surface photons deposit at their instant");
  // 0, as when absent: derived (GatherCosts).
  const float gather = props.getFloat("gather_fraction", 0.0f, Range::closed(0, 1),
                                      "the probability that a camera segment gathers beams; 0: derived");
  s.gatherFraction = gather > 0.0f ? gather : -1.0f;
  // 0, as when absent: derived (withSurfaceGatherFor).
  const float surfaceGather = props.getFloat("surface_gather_fraction", 0.0f, Range::closed(0, 1),
                                             "the probability that a camera sample gathers surface photons; 0: derived");
  s.surfaceGatherFraction = surfaceGather > 0.0f ? surfaceGather : -1.0f;
  s.gatherRoulette = props.getFloat("gather_roulette", s.gatherRoulette, Range::closed(0, 1),
                                    "the camera transmittance at which a gather's Russian roulette starts; 0: never");
  s.alpha = props.getFloat("alpha", s.alpha, Range::leftOpen(0, 1));
  static_cast<PathDepthSettings&>(s) = PathDepthSettings::read(props);
  s.store = props.getEnum(
      "store", BeamStore::All,
      {{"all", BeamStore::All, "every scattering order"}, {"single", BeamStore::Single, "single scattering"}});
  s.volumeEstimator = props.getEnum("volume_estimator", VolumeEstimator::Beams,
                                    {{"beams", VolumeEstimator::Beams, "photon beams, ray x beam 1D"},
                                     {"points", VolumeEstimator::Points, "photon points, the beam radiance estimate"}});
  s.observerTime = props.getBool("observer_time", true);
  s.hideEmitters = props.getBool("hide_emitters", false);
  s.timeSplitting = props.getBool("time_splitting", true);
  s.stratifiedPhotons = props.getBool("stratified_photons", true);
  s.timeGating = props.getBool("time_gating", true);
  s.beforeWindowRate = props.getFloat("before_window_rate", s.beforeWindowRate, Range::closed(0, 1),
                                      "the share of estimates landing wholly before the window that are made");
  return s;
}

BeamSettings BeamSettings::resolved(const BoundingBox3f& sceneBounds) const {
  BeamSettings s = *this;
  if (s.surfaceRadius > 0.0f) return s;
  // No shapes: no surface photons are stored or gathered, the radius is unused.
  if (!sceneBounds.valid()) {
    s.surfaceRadius = 1.0f;
    return s;
  }
  float diagonal = 2.0f * sceneBounds.boundingRadius();
  if (!(diagonal > 0.0f) || !std::isfinite(diagonal))
    throw Error(location,
                "transient_beams: the scene has no finite extent to derive the surface kernel radius "
                "from; give \"surface_radius\"");
  s.surfaceRadius = SurfaceRadiusFraction * diagonal;
  return s;
}

namespace {

/// The beams' spread, for a view with no probes (no medium seen straight from
/// the camera): with total beam length L in a bounding box of volume V, a
/// segment of length V^(1/3) through beams spread evenly and isotropically
/// meets about L V^(1/3) 2r (pi/4) / V of them (pi/4: the mean |sin| of
/// isotropic directions), so r = 2 H V^(2/3) / (pi L); P photon points meet
/// it in a cylinder of volume pi r^2 V^(1/3): r = sqrt(H V^(2/3) / (pi P)).
/// At most 1 % of the scene's diagonal; beams spanning no volume: 0.5 %.
double spreadRadius(const std::vector<Beam>& beams, bool points, const BoundingBox3f& sceneBounds) {
  double length = 0.0;
  BoundingBox3f box;
  for (const Beam& b : beams) {
    length += b.length;
    box.expand(b.origin);
    box.expand(b.origin + b.direction * b.length);
  }
  const Vec3f e = box.valid() ? box.extents() : Vec3f(0.0f);
  const double volume = double(e.x) * double(e.y) * double(e.z);
  const double area = std::cbrt(volume * volume);  // V^(2/3)
  const double h = BeamSettings::TargetPairHits;
  double r = 0.0;
  if (points)
    r = volume > 0.0 && !beams.empty() ? std::sqrt(h * area / (Pi * double(beams.size()))) : 0.0;
  else
    r = volume > 0.0 && length > 0.0 ? 2.0 * h * area / (Pi * length) : 0.0;
  const float diagonal = 2.0f * sceneBounds.boundingRadius();
  if (!(r > 0.0) || !std::isfinite(r)) r = BeamRadiusFraction * diagonal;
  if (diagonal > 0.0f && std::isfinite(diagonal)) r = std::min(r, double(MaxBeamRadiusFraction * diagonal));
  return r;
}

}  // namespace

BeamSettings BeamSettings::withBeamRadiusFrom(const std::vector<Beam>& beams, const std::vector<ProbeSegment>& probes,
                                              const TimeGrid& grid, const BoundingBox3f& sceneBounds,
                                              DerivedRadius* chosen, double lightBound, const SceneCoverage* coverage,
                                              const DerivedRadius* sizedFor) const {
  BeamSettings s = *this;
  if (s.radius > 0.0f) return s;
  DerivedRadius d;
  const bool points = volumeEstimator == VolumeEstimator::Points;
  d.density = sizedFor         ? sizedFor->density
              : probes.empty() ? spreadRadius(beams, points, sceneBounds)
                               : densityRadius(beams, probes, TargetPairHits, gatherRoulette);
  // The time bound at the largest index a pair's OPL can run at.
  double eta = 0.0;
  for (const ProbeSegment& p : probes) eta = std::max(eta, double(p.segment.eta));
  for (const Beam& b : beams) eta = std::max(eta, double(b.eta));
  d.time = timeRadius(grid, eta);
  // Beams are extended past the boundaries they end on
  // (boundary_extension.h), which leaves BoundaryLossLeft of the loss: the
  // bound is 12.6x larger for them. Its failures at such radii were the
  // light's leak (now the light bound, light_leak.h) and the extension's
  // timing before a beam's start (ray_beam.cpp; random media seed 2).
  // Photon points are not extended: the fog box's points read 6 % below
  // beams at the relaxed radius (docs/design/photon-beams.md, "Relaxing the
  // boundary bound for beams").
  d.boundary = boundaryRadius(probes, /*extended=*/!points);
  d.light = lightBound;
  // The planar model misses curved boundaries (boundary_coverage.h: lines
  // beside a beam grazing a convex medium meet no extension; random media
  // seeds 23 and 21 lost 1.9 % and 3.8 % at the planar radius): the loss
  // counted on the scene at the radius the other bounds allow, shrunk
  // until it holds.
  if (coverage && !points)
    d.boundary = std::min(d.boundary, coveredBoundaryRadius(coverage->scene, beams, coverage->probes,
                                                            std::min({d.density, d.boundary, d.light, d.time})));
  // Beams: the time bound made to hold for oblique pairs, whose footprint
  // along the camera segment is up to 1 / sin(theta) longer (radius_rule.h).
  // Photon points have no such pairs (a point's kernel is a ball).
  // Beams traced for an earlier derivation keep its oblique bound: it holds
  // up to that derivation's cap, and on more beams it only finds more of
  // E[W^2]'s logarithmically divergent near-parallel tail (the box lit from
  // outside, 100000 beam photons instead of 10000: r 0.0049 -> 0.0032,
  // relMSE 0.175 -> 0.357 at equal passes). Derived anew only when the
  // recounted boundary lifts the cap.
  const double cap = std::min({d.density, d.boundary, d.light});
  const bool keepTime = sizedFor && cap <= std::min({sizedFor->density, sizedFor->boundary, sizedFor->light});
  if (keepTime)
    d.time = sizedFor->time;
  else if (!points)
    d.time = obliqueTimeRadius(beams, probes, grid, eta, cap);
  d.radius = std::min({d.density, d.time, d.boundary, d.light});
  // Nothing bounds it (a steady film, beams too few to reach the target, no
  // probes' boundary): the beams' spread.
  if (!std::isfinite(d.radius)) d.radius = std::min(spreadRadius(beams, points, sceneBounds), d.radius);
  if (chosen) *chosen = d;
  s.radius = float(d.radius);
  if (!(s.radius > 0.0f) || !std::isfinite(s.radius))
    throw Error(location,
                "transient_beams: cannot derive a beam radius (no beams and no scene extent); give \"radius\"");
  return s;
}

BeamSettings BeamSettings::withBeamsForRadius(const DerivedRadius& derived) const {
  BeamSettings s = *this;
  if (beamPhotonCountGiven || !(derived.radius > 0.0) || !(derived.density > derived.radius) ||
      !std::isfinite(derived.density))
    return s;
  const double ratio = derived.density / derived.radius;
  const double wanted = double(beamPhotons()) * (volumeEstimator == VolumeEstimator::Points ? ratio * ratio : ratio);
  s.beamPhotonCount = wanted >= double(photonCount) ? 0 : int64_t(std::ceil(wanted));
  return s;
}

float BeamSettings::beamRadius(int pass) const {
  // The 1D kernel (beams) shrinks r, the 2D kernel (points) r^2 by the factor.
  const double factor = reduction(alpha, pass);
  return float(radius * (volumeEstimator == VolumeEstimator::Points ? std::sqrt(factor) : factor));
}

BeamSettings BeamSettings::withSurfaceTimeWidthFor(const TimeGrid& grid) const {
  BeamSettings s = *this;
  if (s.surfaceTimeWidth < 0.0f) {
    const double w = std::min(TimeBinFraction * grid.binWidth, 2.0 * double(s.surfaceRadius));
    s.surfaceTimeWidth = grid.bins > 0 && w >= grid.binWidth ? float(w) : 0.0f;
  }
  return s;
}

double GatherCosts::fraction() const {
  // Nanoseconds per operation (AMD EPYC, one thread; fog box and ToF port profiles).
  constexpr double Ray = 2000.0, SurfaceQuery = 2500.0, SurfacePhoton = 60.0, Photon = 4000.0, Piece = 400.0,
                   Stored = 50.0, Box = 60.0, Candidate = 40.0, Pair = 250.0;
  const double G = gathersPerSample * (Box * boxes + Candidate * candidates + Pair * pairs);
  const double S = Ray + SurfaceQuery * surfaceQueries + SurfacePhoton * surfacePhotons +
                   Photon * photonsPerSample + Piece * piecesPerSample + Stored * storedPerSample;
  if (!(G > 0.0) || !std::isfinite(G) || !std::isfinite(S)) return 1.0;
  const double floor = std::min(1.0, std::max(MinGatherFraction, 1.0 / std::max(samplesPerPixel, 1.0)));
  return std::clamp(std::sqrt(S / (RouletteVarianceShare * G)), floor, 1.0);
}

BeamSettings BeamSettings::withSurfaceGatherFor(uint32_t spp) const {
  BeamSettings s = *this;
  if (s.surfaceGatherFraction < 0.0f)
    s.surfaceGatherFraction =
        float(std::clamp(SurfaceGathersPerPixel / double(std::max<uint32_t>(spp, 1)), MinSurfaceGatherFraction, 1.0));
  return s;
}

float BeamSettings::surfaceRadiusOf(int pass) const {
  const double factor = reduction(alpha, pass);
  // r^2 by the factor (2D kernel), or by its square root when the time kernel makes it 3D.
  return float(surfaceRadius * (surfaceTimeWidth > 0.0f ? std::sqrt(std::sqrt(factor)) : std::sqrt(factor)));
}

float BeamSettings::surfaceTimeWidthOf(int pass) const {
  return surfaceTimeWidth > 0.0f ? float(surfaceTimeWidth * std::sqrt(reduction(alpha, pass))) : 0.0f;
}

}  // namespace femto::beams
