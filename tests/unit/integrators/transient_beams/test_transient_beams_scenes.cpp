// transient_beams on the features the fog Cornell box does not exercise, each
// against transient_path on a small scene (per coarse time bin and the steady
// image, transient_agreement_util.h): a heterogeneous (grid) medium, area,
// spot, projector, directional and constant-sky photons, hide_emitters, a
// medium inside a glass sphere nested in another medium, phase-function and
// wall (BSDF) scattering delays, and gaussian / box / continuous emitter
// pulses. Every
// render also checks that no NaN or Inf reaches the film.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <femto/image/image_io.h>

#include "continuous_pulse_check.h"
#include "media_test_util.h"
#include "render_test_util.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

/// One small scene, rendered by both integrators.
struct BeamsCase {
  std::string content;         // media, emitters and shapes
  bool room = true;            // a closed diffuse room (side 4, normals inward) around everything
  bool foggyRoom = true;       // the room's air and the sensor are the medium "fog" (defined in `content`)
  std::string shared;          // integrator parameters both take (max_depth, hide_emitters)
  std::string wallParams;      // more parameters of the walls' diffuse BSDF (e.g. a scattering delay)
  std::string sensor = R"(<transform name="to_world"><lookat origin="0, 0, 1.9" target="0, 0, 0" up="0, 1, 0"/></transform>)";
  int bins = 6;
  double start = 0.0;
  double binWidth = 2.0;       // [0, 12): direct light, fog and the first wall bounces
  int beamSpp = 2, pathSpp = 64, photons = 20000, runs = 6;
  std::filesystem::path dir = std::filesystem::temp_directory_path();  // where relative file names resolve
};

std::string sceneXml(const BeamsCase& s, bool beams) {
  const std::string integrator =
      beams ? str(R"(<integrator type="transient_beams">)", s.shared, R"(<integer name="photon_count" value=")",
                  s.photons, R"("/></integrator>)")
            : str(R"(<integrator type="transient_path">)", s.shared, "</integrator>");
  const std::string fog = s.foggyRoom ? R"(<ref name="exterior" id="fog"/>)" : "";
  const std::string walls =
      s.room ? str(R"(<shape type="cube"><transform name="to_world"><scale value="2"/></transform>
    <boolean name="flip_normals" value="true"/>)", fog, R"(<bsdf type="diffuse"><float name="reflectance" value="0.6"/>)", s.wallParams, R"(</bsdf></shape>)")
             : "";
  return str(R"(<scene version="3.0.0">)", integrator, s.content, walls, R"(
  <sensor type="perspective"><float name="fov" value="70"/>)", s.foggyRoom ? R"(<ref id="fog"/>)" : "", s.sensor, R"(
    <sampler type="independent"><integer name="sample_count" value=")", beams ? s.beamSpp : s.pathSpp, R"("/></sampler>
    <film type="transient"><integer name="width" value="10"/><integer name="height" value="10"/>
      <integer name="temporal_bins" value=")", s.bins, R"("/><float name="start_opl" value=")", s.start, R"("/>
      <float name="bin_width_opl" value=")", s.binWidth, R"("/><boolean name="write_frames" value="false"/>
      <rfilter type="box"/></film>
  </sensor>
</scene>)");
}

/// Both integrators on `s`: per bin and steady, within 5 sigma of the runs'
/// spread plus the kernels' bias allowance (KernelBias).
void expectBeamsAgreeWithPath(const BeamsCase& s, const std::string& name) {
  auto beams = loadSceneStrict(sceneXml(s, true), s.dir), path = loadSceneStrict(sceneXml(s, false), s.dir);
  std::vector<Mean> b = imageSums(beams, "beams-" + name, s.runs), p = imageSums(path, "path-" + name, s.runs);
  double total = 0.0;
  for (const Mean& m : p) total += m.mean();
  ASSERT_GT(total, 0.0) << "the scene is lit";
  expectAgree(b, p, name.c_str(), KernelBias);
}

const char* Fog = R"(<medium type="homogeneous" id="fog"><float name="sigma_t" value="0.4"/>
    <float name="albedo" value="0.8"/></medium>)";
const char* PointLightElement = R"(<emitter type="point"><point name="position" x="0.5" y="1.7" z="1"/>
    <float name="intensity" value="3"/></emitter>)";

}  // namespace

TEST(TransientBeamsScenes, HeterogeneousMediumAgreesWithTransientPath) {
  // Photon free flights by spectral/delta tracking through the grid, beam
  // and camera transmittance by ratio tracking, sigma_s(x) where the camera
  // segment meets the beam.
  BeamsCase s;
  s.dir = scratchDir("beams-grid");
  writeDensityGrid(s.dir / "density.vol", 5, 2.0f);
  // transient_path's noise dominates the tolerance here: more samples make
  // the test see e.g. sigma_s taken at the beam's start instead of at the
  // camera segment (steady image 8 % too bright).
  s.pathSpp = 256;
  s.content = str(R"(<medium type="heterogeneous" id="fog">
    <volume name="sigma_t" type="gridvolume"><string name="filename" value="density.vol"/></volume>
    <float name="scale" value="0.6"/><float name="albedo" value="0.8"/></medium>)", PointLightElement);
  expectBeamsAgreeWithPath(s, "grid");
}

TEST(TransientBeamsScenes, AreaLightPhotonsAgreeWithTransientPath) {
  // A one-sided rectangle light under the ceiling facing down and a sphere
  // light, both seen by the camera: photon positions, cosine directions and
  // power from area emitters, emitters picked in proportion to power. The
  // emitters seen directly are hidden (HiddenEmittersAgreeWithTransientPath
  // tests that): their pixel coverage noise would swamp the light they cast.
  BeamsCase s;
  s.shared = R"(<boolean name="hide_emitters" value="true"/>)";
  s.beamSpp = 4;
  s.pathSpp = 256;
  s.content = str(Fog, R"(
  <shape type="rectangle"><transform name="to_world"><scale value="0.6"/><rotate x="1" angle="90"/>
      <translate x="-0.5" y="1.6" z="-0.5"/></transform><ref name="exterior" id="fog"/>
    <emitter type="area"><rgb name="radiance" value="3, 2.5, 2"/></emitter></shape>
  <shape type="sphere"><point name="center" x="0.8" y="-1" z="-0.6"/><float name="radius" value="0.25"/>
    <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf><emitter type="area"><rgb name="radiance" value="2, 3, 4"/></emitter></shape>)");
  expectBeamsAgreeWithPath(s, "area");
}

TEST(TransientBeamsScenes, SpotAndProjectorPhotonsAgreeWithTransientPath) {
  // Oriented point lights: a spot's cone (falloff between beam_width and the
  // cutoff) and a projector's frustum light the fog and the walls.
  BeamsCase s;
  s.content = str(Fog, R"(
  <emitter type="spot"><transform name="to_world"><lookat origin="-1, 1.5, 0" target="0, -2, -0.5"/></transform>
    <float name="intensity" value="20"/><float name="cutoff_angle" value="25"/><float name="beam_width" value="15"/></emitter>
  <emitter type="projector"><transform name="to_world"><lookat origin="1.5, 0, -1" target="-2, 0.5, -1"/></transform>
    <float name="fov" value="40"/><float name="scale" value="4"/></emitter>)");
  expectBeamsAgreeWithPath(s, "spot");
}

/// A fog cube (index-matched boundary) on a floor, seen from outside, lit by
/// `emitter` (an emitter at infinity).
BeamsCase fogCubeOnAFloor(const std::string& emitter) {
  BeamsCase s;
  s.room = s.foggyRoom = false;
  s.sensor = R"(<transform name="to_world"><lookat origin="0.5, 1.5, 4" target="0, -0.3, 0" up="0, 1, 0"/></transform>)";
  s.content = str(Fog, R"(
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="3"/><rotate x="1" angle="-90"/>
      <translate y="-1.5"/></transform><bsdf type="diffuse"><float name="reflectance" value="0.6"/></bsdf></shape>
  )", emitter);
  return s;
}

TEST(TransientBeamsScenes, DirectionalLightPhotonsAgreeWithTransientPath) {
  // Light from infinity has no finite path: both integrators start its time
  // at the outermost surface the light crosses (transient_path's next-event
  // estimation counts the shadow ray up to its last boundary; photons start
  // their OPL at their first surface).
  BeamsCase s = fogCubeOnAFloor(R"(<emitter type="directional"><vector name="direction" x="0.4" y="-1" z="-0.3"/>
    <float name="irradiance" value="2"/></emitter>)");
  expectBeamsAgreeWithPath(s, "directional");
}

TEST(TransientBeamsScenes, ConstantEnvironmentPhotonsAgreeWithTransientPath) {
  // The same scene under a uniform sky instead: photons from every direction
  // (the same clock rule), the sky seen behind the cube.
  BeamsCase s = fogCubeOnAFloor(R"(<emitter type="constant"><rgb name="radiance" value="0.5, 0.6, 0.7"/></emitter>)");
  s.beamSpp = 8;  // the floor's next-event estimates dominate the noise
  s.runs = 8;
  expectBeamsAgreeWithPath(s, "constant");
}

TEST(TransientBeamsScenes, HiddenEmittersAgreeWithTransientPath) {
  // hide_emitters blacks out the emitter the camera sees directly (through
  // the fog), not its reflection in the mirror sphere nor the light it casts.
  BeamsCase s;
  s.shared = R"(<boolean name="hide_emitters" value="true"/>)";
  s.content = str(Fog, R"(
  <shape type="sphere"><point name="center" x="-0.5" y="0.8" z="0"/><float name="radius" value="0.35"/>
    <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf><emitter type="area"><rgb name="radiance" value="4, 5, 6"/></emitter></shape>
  <shape type="sphere"><point name="center" x="0.6" y="-1.2" z="0"/><float name="radius" value="0.6"/>
    <ref name="exterior" id="fog"/><bsdf type="conductor"/></shape>)");
  expectBeamsAgreeWithPath(s, "hidden");
}

TEST(TransientBeamsScenes, MediumInsideGlassNestedInFogAgreesWithTransientPath) {
  // A glass sphere (int_ior 1.5) filled with a dense medium of index 1.5,
  // standing in the room's fog: camera paths and photons refract into it,
  // beams of the inner medium scatter only there, and time runs at eta 1.5
  // inside. The light is an area sphere so transient_path can reach it from
  // inside the glass (through the refraction, by hitting it).
  BeamsCase s;
  s.shared = R"(<boolean name="hide_emitters" value="true"/>)";  // as for the area lights
  s.beamSpp = 4;
  s.pathSpp = 256;
  s.runs = 10;  // sees photons that keep the fog's medium inside the glass (steady image 13 % too dark)
  s.content = str(Fog, R"(
  <medium type="homogeneous" id="inner"><float name="sigma_t" value="2"/><float name="albedo" value="0.9"/>
    <float name="eta" value="1.5"/></medium>
  <shape type="sphere"><point name="center" x="0" y="-0.5" z="-0.4"/><float name="radius" value="1.1"/>
    <ref name="interior" id="inner"/><ref name="exterior" id="fog"/>
    <bsdf type="dielectric"><float name="int_ior" value="1.5"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="0.9" y="1.1" z="0.3"/><float name="radius" value="0.4"/>
    <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf><emitter type="area"><rgb name="radiance" value="6"/></emitter></shape>)");
  expectBeamsAgreeWithPath(s, "glass-medium");
}

TEST(TransientBeamsScenes, PhaseDelaysAgreeWithTransientPath) {
  // Every scattering in the fog takes a fixed delay plus an exponential
  // lifetime: photons add them at each scattering, the camera side once per
  // ray x beam pair. Bins narrower than the delays so a missing or doubled
  // delay moves energy between bins.
  BeamsCase s;
  s.bins = 8;
  s.binWidth = 1.5;
  s.content = str(R"(<medium type="homogeneous" id="fog"><float name="sigma_t" value="0.4"/>
    <float name="albedo" value="0.8"/><phase type="hg"><float name="g" value="0.4"/>
    <float name="delay" value="1"/><float name="lifetime" value="0.8"/></phase></medium>)", PointLightElement);
  expectBeamsAgreeWithPath(s, "delays");
}

TEST(TransientBeamsScenes, WallDelaysAgreeWithTransientPath) {
  // A room without media whose walls delay every bounce by 0.7 plus an
  // exponential lifetime of mean 0.3: the camera side adds it at its surface
  // vertex (before next-event estimation and the photon gather), photons at
  // each bounce. Bins of 1 over [5, 15), where the direct light (from
  // OPL 5.5 on) and the first bounces arrive: without the camera's delay
  // the direct light would arrive a bin early, without the photons' the
  // indirect light too early and too bright in the window.
  BeamsCase s;
  s.foggyRoom = false;
  s.wallParams = R"(<float name="delay" value="0.7"/><float name="lifetime" value="0.3"/>)";
  s.bins = 10;
  s.start = 5.0;
  s.binWidth = 1.0;
  s.content = PointLightElement;
  expectBeamsAgreeWithPath(s, "wall-delays");
}

TEST(TransientBeamsScenes, GaussianAndBoxPulsesAgreeWithTransientPath) {
  // Each contribution carries the pulse of the emitter its light came from:
  // a gaussian point light late by 4 and an area sphere emitting over [0, 2],
  // so light credited to the wrong emitter lands bins away.
  BeamsCase s;
  s.content = str(Fog, R"(
  <emitter type="point"><point name="position" x="0.5" y="1.7" z="1"/><float name="intensity" value="3"/>
    <string name="pulse" value="gaussian"/><float name="pulse_sigma" value="0.5"/><float name="pulse_offset" value="4"/></emitter>
  <shape type="sphere"><point name="center" x="-0.8" y="-1" z="-0.6"/><float name="radius" value="0.3"/>
    <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf><emitter type="area"><rgb name="radiance" value="3"/>
    <string name="pulse" value="box"/><float name="pulse_width" value="2"/></emitter></shape>)");
  expectBeamsAgreeWithPath(s, "pulses");
}

TEST(TransientBeamsScenes, ContinuousEmissionIsTheRunningIntegralOfTheDiracRender) {
  // Pulses draw no random numbers, so the same seed gives the same photons
  // and camera samples: a continuously emitting light's bins must lie between
  // the running integrals of the Dirac render's bins (continuous_pulse_check.h).
  BeamsCase s;
  s.content = std::string(Fog) + PointLightElement;
  std::string continuousLight = R"(<emitter type="point"><point name="position" x="0.5" y="1.7" z="1"/>
    <float name="intensity" value="3"/><string name="pulse" value="continuous"/></emitter>)";
  BeamsCase c = s;
  c.content = std::string(Fog) + continuousLight;
  auto dir = scratchDir("beams-continuous");
  Rendered dirac = render(loadSceneStrict(sceneXml(s, true)), dir / "dirac.exr", 9);
  Rendered continuous = render(loadSceneStrict(sceneXml(c, true)), dir / "cont.exr", 9);
  Bitmap before = readImage(dir / "dirac_before.exr");
  double scale = 0.0;
  for (int y = 0; y < dirac.steady.height; ++y)
    for (int x = 0; x < dirac.steady.width; ++x)
      for (int ch = 0; ch < 3; ++ch) scale = std::max(scale, double(dirac.steady.pixel(x, y)[ch]));
  ASSERT_GT(scale, 0.0);
  EXPECT_TRUE(isRunningIntegralOf(continuous.volume, dirac.volume, before, dirac.w, dirac.h, dirac.bins, scale));
  std::filesystem::remove_all(dir);
}
