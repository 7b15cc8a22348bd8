// transient_beams' photon pass: power and OPL bookkeeping of the beams and
// surface photons it stores (emitter choice in proportion to power, eta per
// medium, scattering delays, glass delays), and maps that do not depend on
// the thread count.
#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>

#include <femto/math/pcg32.h>
#include <femto/render/scene.h>
#include <transient_beams/photon_tracer.h>
#include <transient_beams/ray_beam.h>

#include "media_test_util.h"

using namespace femto;
using namespace femto::test;
using femto::beams::Beam;
using femto::beams::BeamSettings;
using femto::beams::PhotonPass;
using femto::beams::SurfacePhoton;
using femto::beams::tracePhotonPass;

namespace {

const float Eta = 1.33f, Delay = 0.5f;

/// Two point lights in an unbounded homogeneous medium of index 1.33 whose
/// phase function delays every scattering by 0.5.
std::shared_ptr<Scene> litMedium() {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value="0.8"/><float name="albedo" value="0.9"/>
    <float name="eta" value=")",
                             Eta, R"("/><phase type="isotropic"><float name="delay" value=")", Delay, R"("/></phase>
  </medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x="0.8" y="0" z="1"/><float name="intensity" value="2"/></emitter>
  <emitter type="point"><point name="position" x="-1" y="0.5" z="0"/><rgb name="intensity" value="1, 0.5, 0"/></emitter>
</scene>)"));
}

/// Every photon leaves beams (not only the integrator's default first 10000).
BeamSettings photonSettings(int64_t photons) {
  BeamSettings s;
  s.photonCount = photons;
  s.beamPhotonCount = 0;
  return s;
}

}  // namespace

TEST(TransientBeamsPhotons, FirstBeamsCarryTheEmittedPowerFromTheLights) {
  auto scene = litMedium();
  const int64_t n = 20000;
  PhotonPass pass = tracePhotonPass(*scene, photonSettings(n), 17, Infinity);
  const Point3f a(0.8f, 0.0f, 1.0f), b(-1.0f, 0.5f, 0.0f);
  const Color3f powerA = Color3f(2.0f) * (4.0f * Pi), powerB = Color3f(1.0f, 0.5f, 0.0f) * (4.0f * Pi);
  const Color3f total = powerA + powerB;
  // Emitters are picked in proportion to their (channel-average) power; a
  // photon carries its emitter's power over the probability of that pick.
  const double p = powerA.average() / total.average();
  const Color3f carriedA = powerA / float(p), carriedB = powerB / float(1.0 - p);
  double firstPower[3] = {0.0, 0.0, 0.0};
  int first = 0, fromA = 0;
  for (const Beam& beam : pass.beams) {
    if (beam.depth != 1) continue;
    ++first;
    bool isA = distance(beam.origin, a) < 1e-5f;
    ASSERT_TRUE(isA || distance(beam.origin, b) < 1e-5f) << "a first beam starts at a light";
    fromA += isA;
    EXPECT_EQ(beam.emitter, isA ? 0 : 1) << "beams name the emitter (its pulse) in scene order";
    EXPECT_EQ(beam.opl, 0.0) << "emission is a Dirac pulse at OPL 0";
    EXPECT_FLOAT_EQ(beam.eta, Eta);
    EXPECT_NE(beam.medium, nullptr);
    const Color3f& carried = isA ? carriedA : carriedB;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(beam.power[c], carried[c], 1e-5f * carried[c] + 1e-6f);
    for (int c = 0; c < 3; ++c) firstPower[c] += beam.power[c];
  }
  EXPECT_EQ(first, n) << "every photon starts with one beam (the medium is unbounded)";
  EXPECT_NEAR(double(fromA) / n, p, 5.0 * std::sqrt(p * (1.0 - p) / n)) << "binomial, 5 sigma";
  // The first beams' mean power estimates the lights' total power (5 sigma of
  // the two-valued photon power).
  for (int c = 0; c < 3; ++c) {
    double variance = p * carriedA[c] * carriedA[c] + (1.0 - p) * carriedB[c] * carriedB[c] - total[c] * total[c];
    EXPECT_NEAR(firstPower[c] / double(n), total[c], 5.0 * std::sqrt(std::max(0.0, variance) / n) + 1e-4) << c;
  }
}

TEST(TransientBeamsPhotons, BeamOplIsEtaTimesDistanceTravelledPlusScatteringDelays) {
  auto scene = litMedium();
  PhotonPass pass = tracePhotonPass(*scene, photonSettings(5000), 23, Infinity);
  const Point3f lights[2] = {Point3f(0.8f, 0.0f, 1.0f), Point3f(-1.0f, 0.5f, 0.0f)};
  int second = 0, deeper = 0;
  for (const Beam& beam : pass.beams) {
    if (beam.depth == 1) continue;
    // The photon reached this beam's origin from one of the lights along a
    // path at least as long as the straight line, with depth - 1 delays.
    double straight = std::min(distance(beam.origin, lights[0]), distance(beam.origin, lights[1]));
    double lower = Eta * straight + (beam.depth - 1) * Delay;
    if (beam.depth == 2) {
      // One straight segment from the light that emitted it: exact.
      double fromA = Eta * distance(beam.origin, lights[0]) + Delay;
      double fromB = Eta * distance(beam.origin, lights[1]) + Delay;
      EXPECT_NEAR(std::min(std::abs(beam.opl - fromA), std::abs(beam.opl - fromB)), 0.0, 1e-4 * (1.0 + beam.opl));
      ++second;
    } else {
      EXPECT_GE(beam.opl, lower - 1e-4 * (1.0 + beam.opl));
      ++deeper;
    }
  }
  EXPECT_GT(second, 1000);
  EXPECT_GT(deeper, 1000);
}

TEST(TransientBeamsPhotons, StoreSingleKeepsOnlyUnscatteredBeams) {
  auto scene = litMedium();
  BeamSettings settings = photonSettings(3000);
  settings.store = beams::BeamStore::Single;
  PhotonPass pass = tracePhotonPass(*scene, settings, 5, Infinity);
  EXPECT_EQ(pass.beams.size(), 3000u);
  for (const Beam& beam : pass.beams) EXPECT_EQ(beam.depth, 1);
}

TEST(TransientBeamsPhotons, GlassDelaysPhotonsByItsIndexAlongTheRefractedPath) {
  // A point light at the origin above a glass slab (ior 1.5, z in [1, 1.4])
  // and a diffuse floor at z = 3 facing it. Photons crossing the slab
  // (depth 3: light -> slab, inside, -> floor) arrive at OPL
  // (3 - h) / cos(theta) + 1.5 h / cos(theta'), sin(theta) = 1.5 sin(theta'),
  // theta read from the direction they arrive from (the slab keeps it).
  const float h = 0.4f;
  auto scene = loadSceneStrict(str(R"(<scene version="3.0.0">
  <emitter type="point"><point name="position" x="0" y="0" z="0"/><float name="intensity" value="1"/></emitter>
  <shape type="cube">
    <transform name="to_world"><scale x="20" y="20" z=")",
                                   h / 2, R"("/><translate z=")", 1 + h / 2, R"("/></transform>
    <bsdf type="dielectric"><float name="int_ior" value="1.5"/><float name="ext_ior" value="1"/></bsdf>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/><rotate x="1" angle="180"/><translate z="3"/></transform>
    <bsdf type="diffuse"/>
  </shape>
</scene>)"));
  PhotonPass pass = tracePhotonPass(*scene, photonSettings(20000), 29, Infinity);
  EXPECT_TRUE(pass.beams.empty()) << "no medium, no beams";
  int checked = 0;
  for (const SurfacePhoton& p : pass.surfacePhotons) {
    EXPECT_GE(p.depth, 3) << "photons straight from the light are next-event estimation's, not stored";
    if (p.depth != 3 || std::abs(p.p.z - 3.0f) > 1e-3f) continue;
    double cosTheta = -p.wi.z, sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    double cosInside = std::sqrt(1.0 - sinTheta * sinTheta / (1.5 * 1.5));
    double expected = (3.0 - h) / cosTheta + 1.5 * h / cosInside;
    // Rays leave surfaces offset by RayEpsilon (1 + max |p|) (interaction.cpp),
    // which shifts the refracted path by about that much at each of the two
    // glass vertices; the glass delay itself is 0.5 h / cos(theta') >= 0.2.
    double offset = RayEpsilon * (1.0 + maxComponent(abs(p.p)));
    EXPECT_NEAR(p.opl, expected, 1e-6 * expected + 6.0 * offset) << "photon at " << p.p;
    ++checked;
  }
  EXPECT_GT(checked, 2000);
}

TEST(TransientBeamsPhotons, OnlyTheFirstBeamPhotonsLeaveBeams) {
  // beam_photon_count = M: photons 0..M-1 leave their beams, every photon its
  // surface photons; each photon is the same as in a pass that stores all
  // (its own random stream), so the beams are exactly those of an M-photon
  // pass and the surface photons those of the full pass. With
  // stratified_photons (on here) photon i's direction depends on its group
  // (the M beam photons, the rest: stratifiedDirection), so the surface
  // photons equal the full pass's only without it; the beams, a group of
  // their own, equal the M-photon pass's either way.
  auto scene = loadSceneStrict(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value="0.6"/><float name="albedo" value="0.9"/></medium>
  <sensor type="perspective"/>
  <emitter type="point"><point name="position" x="0" y="0" z="0"/><float name="intensity" value="1"/></emitter>
  <shape type="sphere"><float name="radius" value="2"/><ref name="interior" id="m"/>
    <bsdf type="diffuse"/></shape>
</scene>)");
  BeamSettings some = photonSettings(3000), all = photonSettings(3000), first = photonSettings(700);
  some.beamPhotonCount = 700;
  all.beamPhotonCount = first.beamPhotonCount = 0;
  PhotonPass a = tracePhotonPass(*scene, some, 41, Infinity), b = tracePhotonPass(*scene, all, 41, Infinity),
             c = tracePhotonPass(*scene, first, 41, Infinity);
  EXPECT_EQ(a.photonCount, 3000u);
  EXPECT_EQ(a.beamPhotonCount, 700u);
  EXPECT_EQ(b.beamPhotonCount, 3000u);
  ASSERT_EQ(a.beams.size(), c.beams.size());
  EXPECT_LT(a.beams.size(), b.beams.size());
  for (size_t i = 0; i < a.beams.size(); ++i)
    ASSERT_TRUE(a.beams[i].origin == c.beams[i].origin && a.beams[i].direction == c.beams[i].direction &&
                a.beams[i].power == c.beams[i].power && a.beams[i].opl == c.beams[i].opl)
        << "beam " << i;
  some.stratifiedPhotons = all.stratifiedPhotons = false;
  a = tracePhotonPass(*scene, some, 41, Infinity), b = tracePhotonPass(*scene, all, 41, Infinity);
  ASSERT_EQ(a.surfacePhotons.size(), b.surfacePhotons.size());
  ASSERT_GT(a.surfacePhotons.size(), 1000u);
  for (size_t i = 0; i < a.surfacePhotons.size(); ++i)
    ASSERT_TRUE(a.surfacePhotons[i].p == b.surfacePhotons[i].p &&
                a.surfacePhotons[i].power == b.surfacePhotons[i].power)
        << "surface photon " << i;
}

TEST(TransientBeamsPhotons, WithoutSurfacesThatStorePhotonsOnlyTheBeamPhotonsAreTraced) {
  // The same medium behind an index-matched boundary (no BSDF: nothing
  // stores a surface photon), then behind a diffuse one. The photons past
  // the beam photons would leave only surface photons: without a surface
  // that stores them they are not traced, and the beams are the same.
  auto sceneWith = [](const char* bsdf) {
    return loadSceneStrict(str(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value="0.6"/><float name="albedo" value="0.9"/></medium>
  <sensor type="perspective"/>
  <emitter type="point"><point name="position" x="0" y="0" z="0"/><float name="intensity" value="1"/></emitter>
  <shape type="sphere"><float name="radius" value="2"/><ref name="interior" id="m"/>)",
                               bsdf, R"(</shape>
</scene>)"));
  };
  auto open = sceneWith(""), walled = sceneWith(R"(<bsdf type="diffuse"/>)");
  EXPECT_FALSE(open->hasSmoothSurfaces());
  EXPECT_TRUE(walled->hasSmoothSurfaces());
  BeamSettings some = photonSettings(3000), first = photonSettings(700);
  some.beamPhotonCount = 700;
  const PhotonPass a = tracePhotonPass(*open, some, 43, Infinity), c = tracePhotonPass(*open, first, 43, Infinity),
                   w = tracePhotonPass(*walled, some, 43, Infinity);
  EXPECT_EQ(a.photonCount, 3000u);  // the surface estimate's N is unchanged
  EXPECT_EQ(a.tracedPhotons, 700u);
  EXPECT_EQ(w.tracedPhotons, 3000u);
  EXPECT_TRUE(a.surfacePhotons.empty());
  EXPECT_GT(w.surfacePhotons.size(), 1000u);
  ASSERT_EQ(a.beams.size(), c.beams.size());
  ASSERT_GT(a.beams.size(), 700u);
  for (size_t i = 0; i < a.beams.size(); ++i)
    ASSERT_TRUE(a.beams[i].origin == c.beams[i].origin && a.beams[i].direction == c.beams[i].direction &&
                a.beams[i].power == c.beams[i].power && a.beams[i].opl == c.beams[i].opl)
        << "beam " << i;
}

TEST(TransientBeamsPhotons, DerivedRadiusGivesAboutTheTargetPairsPerSegment) {
  // Isotropic beams spread evenly over a cube: a segment of the cube's side
  // meets about TargetPairHits of them within the derived radius (the
  // formula's assumptions hold here up to the beams' and segments' ends).
  PCG32 rng(3, 3);
  std::vector<Beam> beams;
  auto direction = [&] {
    float z = 1.0f - 2.0f * rng.nextFloat(), phi = 2.0f * Pi * rng.nextFloat(), s = std::sqrt(1.0f - z * z);
    return Vec3f(s * std::cos(phi), s * std::sin(phi), z);
  };
  auto point = [&] { return Point3f(2.0f * rng.nextFloat(), 2.0f * rng.nextFloat(), 2.0f * rng.nextFloat()); };
  while (beams.size() < 20000) {
    // Chords of the cube [0, 2]^3 through a uniform point: evenly spread, isotropic.
    Point3f p = point();
    Vec3f d = direction();
    float back = Infinity, ahead = Infinity;
    for (int k = 0; k < 3; ++k) {
      if (d[k] == 0.0f) continue;
      float t0 = (0.0f - p[k]) / d[k], t1 = (2.0f - p[k]) / d[k];
      ahead = std::min(ahead, std::max(t0, t1));
      back = std::min(back, -std::min(t0, t1));
    }
    Beam b;
    b.origin = p - d * back;
    b.direction = d;
    b.length = back + ahead;
    b.power = Color3f(1.0f);
    if (b.length > 0.0f) beams.push_back(b);
  }
  // Probes: 64 segments like a camera's in the medium; the density radius
  // is their k-nearest distance, checked on 400 other segments.
  std::vector<femto::beams::ProbeSegment> probes(64);
  for (auto& p : probes) p.segment.ray = Ray(point(), direction()), p.segment.tMax = 2.0f;
  BeamSettings s = photonSettings(1000);
  femto::beams::DerivedRadius derived;
  BeamSettings resolved =
      s.withBeamRadiusFrom(beams, probes, TimeGrid{}, BoundingBox3f(Point3f(0.0f), Point3f(2.0f)), &derived);
  ASSERT_GT(derived.density, 0.0);
  EXPECT_EQ(resolved.radius, float(std::min({derived.density, derived.time, derived.boundary})));
  EXPECT_FALSE(std::isfinite(derived.time)) << "a steady film does not bound it";
  double hits = 0.0;
  const int segments = 400;
  for (int i = 0; i < segments; ++i) {
    femto::beams::CameraSegment seg;
    seg.ray = Ray(point(), direction());
    seg.tMax = 2.0f;  // may leave the cube (fewer beams there), as the probes do
    femto::beams::RayBeamHit hit;
    for (const Beam& b : beams) hits += femto::beams::rayBeamIntersect(seg, b, float(derived.density), hit) ? 1.0 : 0.0;
  }
  const double perSegment = hits / segments;
  std::printf("density radius %g: %.1f pairs per segment (target %g)\n", derived.density, perSegment,
              BeamSettings::TargetPairHits);
  // 64 probes x 25 pairs: the count is known to ~ +-10 % (their spread of lengths inside the cube).
  EXPECT_GT(perSegment, 0.7 * BeamSettings::TargetPairHits);
  EXPECT_LT(perSegment, 1.3 * BeamSettings::TargetPairHits);
  // Beams traced for a derivation (withBeamsForRadius) keep its density
  // bound: twice the beams would halve the radius that meets the target.
  femto::beams::DerivedRadius sized = derived, again;
  sized.density = 0.5 * derived.density;
  std::vector<Beam> twice = beams;
  twice.insert(twice.end(), beams.begin(), beams.end());
  s.withBeamRadiusFrom(twice, probes, TimeGrid{}, BoundingBox3f(Point3f(0.0f), Point3f(2.0f)), &again, Infinity,
                       nullptr, &sized);
  EXPECT_EQ(again.density, sized.density);
  // Its time bound too, unless the boundary now allows more than its cap
  // (a steady film: derived anew, the time bound is +Infinity).
  sized.time = 0.01;
  s.withBeamRadiusFrom(twice, probes, TimeGrid{}, BoundingBox3f(Point3f(0.0f), Point3f(2.0f)), &again, Infinity,
                       nullptr, &sized);
  EXPECT_EQ(again.time, 0.01);
  sized.boundary = 1e-3 * sized.density;
  s.withBeamRadiusFrom(twice, probes, TimeGrid{}, BoundingBox3f(Point3f(0.0f), Point3f(2.0f)), &again, Infinity,
                       nullptr, &sized);
  EXPECT_FALSE(std::isfinite(again.time)) << "the cap was lifted: derived anew";
  s.withBeamRadiusFrom(twice, probes, TimeGrid{}, BoundingBox3f(Point3f(0.0f), Point3f(2.0f)), &again);
  EXPECT_LT(again.density, 0.75 * derived.density) << "derived anew, the density bound follows the beams";
  // A given radius is kept; no beams and no probes fall back to the scene's scale.
  s.radius = 0.125f;
  EXPECT_EQ(s.withBeamRadiusFrom(beams, probes, TimeGrid{}, BoundingBox3f()).radius, 0.125f);
  s.radius = 0.0f;
  float fallback = s.withBeamRadiusFrom({}, {}, TimeGrid{}, BoundingBox3f(Point3f(0.0f), Point3f(2.0f))).radius;
  EXPECT_GT(fallback, 0.0f);
  EXPECT_LT(fallback, 0.1f);
}

TEST(TransientBeamsPhotons, MapsDoNotDependOnTheThreadCount) {
  auto scene = litMedium();
  auto trace = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, size_t(threads));
    return tracePhotonPass(*scene, photonSettings(4000), 99, Infinity);
  };
  PhotonPass one = trace(1), two = trace(2);
  ASSERT_EQ(one.beams.size(), two.beams.size());
  for (size_t i = 0; i < one.beams.size(); ++i) {
    const Beam &x = one.beams[i], &y = two.beams[i];
    ASSERT_TRUE(x.origin == y.origin && x.direction == y.direction && x.length == y.length && x.power == y.power &&
                x.opl == y.opl && x.depth == y.depth)
        << "beam " << i;
  }
}

TEST(TransientBeamsPhotons, AreaLightPhotonsLeaveTheShapeWithCosineDirectionsAndItsPower) {
  // A one-sided square light (side 2, normal +z) in an unbounded medium:
  // every first beam starts on it, leaves on its front side, carries the
  // emitted power L pi A, and its direction cosines follow the cosine
  // (Lambertian) density: mean 2/3 (variance 1/18) and mean square 1/2
  // (variance 1/12), 5 sigma; a uniform hemisphere would give 1/2 and 1/3.
  auto scene = loadSceneStrict(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value="0.1"/><float name="albedo" value="0.5"/></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <shape type="rectangle"><ref name="exterior" id="m"/><ref name="interior" id="m"/>
    <emitter type="area"><rgb name="radiance" value="1, 2, 3"/></emitter></shape>
</scene>)");
  const int64_t n = 20000;
  PhotonPass pass = tracePhotonPass(*scene, photonSettings(n), 31, Infinity);
  const Color3f power = Color3f(1.0f, 2.0f, 3.0f) * (Pi * 4.0f);
  Mean cosine, cosineSq;
  for (const Beam& beam : pass.beams) {
    if (beam.depth != 1) continue;
    ASSERT_NEAR(beam.origin.z, 0.0f, 1e-3f);
    ASSERT_LE(std::max(std::abs(beam.origin.x), std::abs(beam.origin.y)), 1.0f + 1e-5f);
    ASSERT_GT(beam.direction.z, 0.0f) << "emitted on the front side only";
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(beam.power[c], power[c], 1e-5f * power[c]);
    cosine.add(beam.direction.z);
    cosineSq.add(beam.direction.z * beam.direction.z);
  }
  ASSERT_EQ(cosine.count(), n) << "one first beam per photon";
  EXPECT_NEAR(cosine.mean(), 2.0 / 3.0, 5.0 * std::sqrt(1.0 / 18.0 / double(n)));
  EXPECT_NEAR(cosineSq.mean(), 0.5, 5.0 * std::sqrt(1.0 / 12.0 / double(n)));
}
