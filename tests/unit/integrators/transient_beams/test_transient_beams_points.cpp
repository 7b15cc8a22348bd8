// transient_beams with volume_estimator = "points" (photon points, the beam
// radiance estimate; ray_point.h): what the photon pass stores -- one point
// per scattering vertex in a medium, its power in beam units (arriving power
// times T/pdf, so that points and beams estimate the same density), the
// direction it arrived from, its OPL before the vertex's own delay -- the 2D
// kernel's radius schedule, and the radius derived from the first pass.
// End to end (closed form, fog box vs beams, threads): test_transient_beams_media.cpp
// and test_transient_beams_render.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <femto/math/pcg32.h>
#include <femto/render/scene.h>
#include <transient_beams/photon_tracer.h>
#include <transient_beams/ray_point.h>

#include "media_test_util.h"

using namespace femto;
using namespace femto::test;
using femto::beams::Beam;
using femto::beams::BeamSettings;
using femto::beams::BeamStore;
using femto::beams::PhotonPass;
using femto::beams::VolumeEstimator;

namespace {

const float SigmaT = 0.8f, Albedo = 0.9f, Eta = 1.33f, Delay = 0.5f, Intensity = 2.0f;
const Point3f Light(0.8f, 0.0f, 1.0f);

/// A point light in an unbounded homogeneous medium whose phase function
/// delays every scattering by Delay.
std::shared_ptr<Scene> litMedium() {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <medium id="m" type="homogeneous"><float name="sigma_t" value=")", SigmaT, R"("/><float name="albedo" value=")",
                             Albedo, R"("/><float name="eta" value=")", Eta,
                             R"("/><phase type="isotropic"><float name="delay" value=")", Delay, R"("/></phase>
  </medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x=")", Light.x, R"(" y=")", Light.y, R"(" z=")", Light.z,
                             R"("/><float name="intensity" value=")", Intensity, R"("/></emitter>
</scene>)"));
}

BeamSettings pointSettings(int64_t photons) {
  BeamSettings s;
  s.photonCount = photons;
  s.beamPhotonCount = 0;
  s.radius = s.surfaceRadius = 0.05f;
  s.volumeEstimator = VolumeEstimator::Points;
  s.rrDepth = 100;  // no Russian roulette: powers stay exact
  s.maxDepth = 3;   // points of depth 1 and 2 (a photon segment ends paths of at least depth + 1 segments)
  return s;
}

}  // namespace

TEST(TransientBeamsPoints, ScatteringVerticesLeavePointsInBeamUnits) {
  // In a homogeneous medium a free flight has pdf sigma_t T and weight
  // sigma_s T / pdf = albedo, so a point's power is the arriving power / sigma_t:
  // Phi/sigma_t for the first vertex (Phi = 4 pi I), Phi albedo/sigma_t for
  // the second (isotropic phase sampling has weight 1). An unbounded medium
  // always scatters: every photon leaves exactly one first point.
  auto scene = litMedium();
  const int64_t n = 2000;
  PhotonPass pass = tracePhotonPass(*scene, pointSettings(n), 42, Infinity);
  const double phi = 4.0 * Pi * Intensity;
  int first = 0, second = 0;
  for (const Beam& p : pass.beams) {
    ASSERT_EQ(p.length, 0.0f);
    ASSERT_NE(p.medium, nullptr);
    EXPECT_NEAR(length(p.direction), 1.0f, 1e-5f);
    const double expected = p.depth == 1 ? phi / SigmaT : phi * Albedo / SigmaT;
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(p.power[c], expected, 1e-4 * expected) << "depth " << p.depth;
    const double fromLight = distance(p.origin, Light);
    if (p.depth == 1) {
      ++first;
      // Arrived straight from the light: its OPL is eta times the distance, its direction away from the light.
      EXPECT_NEAR(p.opl, Eta * fromLight, 1e-4 * (1.0 + fromLight));
      EXPECT_GT(dot(p.direction, normalize(p.origin - Light)), 0.9999f);
    } else {
      ASSERT_EQ(p.depth, 2);
      ++second;
      // One vertex and its delay behind it, this vertex's delay not yet.
      EXPECT_GE(p.opl, Eta * fromLight + Delay - 1e-4);
    }
  }
  EXPECT_EQ(first, int(n));
  EXPECT_GT(second, n / 2) << "albedo 0.9: most photons scatter twice";
  EXPECT_EQ(pass.beamPhotonCount, uint64_t(n));
}

TEST(TransientBeamsPoints, StoreSingleKeepsOnlyFirstVertices) {
  auto scene = litMedium();
  BeamSettings s = pointSettings(500);
  s.store = BeamStore::Single;
  PhotonPass pass = tracePhotonPass(*scene, s, 7, Infinity);
  EXPECT_EQ(pass.beams.size(), 500u);
  for (const Beam& p : pass.beams) EXPECT_EQ(p.depth, 1);
}

TEST(TransientBeamsPoints, RadiusShrinksLikeA2DKernel) {
  // Knaus and Zwicker 2011: a d-dimensional kernel's variance grows as r^-d,
  // so r^d shrinks by (i + alpha) / (i + 1) per pass: r for beams (1D), r^2
  // for points and surface photons (2D).
  BeamSettings s;
  s.radius = 0.2f;
  s.surfaceRadius = 0.1f;
  s.alpha = 0.5f;
  BeamSettings p = s;
  p.volumeEstimator = VolumeEstimator::Points;
  const double factor2 = 0.5 * (1.5 / 2.0);  // passes 0 -> 2
  EXPECT_NEAR(s.beamRadius(2), 0.2 * factor2, 1e-7);
  EXPECT_NEAR(p.beamRadius(2), 0.2 * std::sqrt(factor2), 1e-7);
  EXPECT_NEAR(p.surfaceRadiusOf(2), 0.1 * std::sqrt(factor2), 1e-7);
  EXPECT_EQ(p.beamRadius(0), 0.2f);
}

TEST(TransientBeamsPoints, DerivedRadiusGivesAboutTheTargetPairsPerSegment) {
  // Points uniform in a cube: a segment of the cube's side meets about
  // TargetPairHits of them within the derived radius r = sqrt(H V^(2/3) / (pi P)).
  PCG32 rng(5, 1);
  auto point = [&] { return Point3f(2.0f * rng.nextFloat(), 2.0f * rng.nextFloat(), 2.0f * rng.nextFloat()); };
  std::vector<Beam> points(20000);
  for (Beam& b : points) b.origin = point(), b.direction = Vec3f(0.0f, 0.0f, 1.0f), b.power = Color3f(1.0f);
  BeamSettings s;
  s.volumeEstimator = VolumeEstimator::Points;
  auto direction = [&] {
    float z = 1.0f - 2.0f * rng.nextFloat(), phi = 2.0f * Pi * rng.nextFloat(), sz = std::sqrt(1.0f - z * z);
    return Vec3f(sz * std::cos(phi), sz * std::sin(phi), z);
  };
  std::vector<femto::beams::ProbeSegment> probes(64);
  for (auto& p : probes) p.segment.ray = Ray(point(), direction()), p.segment.tMax = 2.0f;
  femto::beams::DerivedRadius derived;
  s.withBeamRadiusFrom(points, probes, TimeGrid{}, BoundingBox3f(Point3f(-10.0f), Point3f(12.0f)), &derived);
  // Evenly spread: at least the spread rule's sqrt(H V^(2/3) / (pi P)), which
  // assumes segments inside the cube; up to sqrt(2) x that when half of each leaves it.
  const double spread = std::sqrt(BeamSettings::TargetPairHits * 4.0 / (Pi * 20000.0));
  EXPECT_GT(derived.density, spread);
  EXPECT_LT(derived.density, 1.6 * spread);
  BeamSettings resolved = s;
  resolved.radius = float(derived.density);
  double hits = 0.0;
  const int segments = 400;
  for (int i = 0; i < segments; ++i) {
    float z = 1.0f - 2.0f * rng.nextFloat(), phi = 2.0f * Pi * rng.nextFloat(), sz = std::sqrt(1.0f - z * z);
    femto::beams::CameraSegment seg;
    seg.ray = Ray(point(), Vec3f(sz * std::cos(phi), sz * std::sin(phi), z));
    seg.tMax = 2.0f;  // V^(1/3); may leave the cube (fewer points there)
    femto::beams::RayBeamHit hit;
    for (const Beam& b : points) hits += femto::beams::rayPointIntersect(seg, b, resolved.radius, hit) ? 1.0 : 0.0;
  }
  const double perSegment = hits / segments;
  std::printf("derived point radius %g: %.1f pairs per segment (target %g)\n", resolved.radius, perSegment,
              BeamSettings::TargetPairHits);
  EXPECT_GT(perSegment, 0.7 * BeamSettings::TargetPairHits);
  EXPECT_LT(perSegment, 1.3 * BeamSettings::TargetPairHits);
}
