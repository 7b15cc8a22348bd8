// The surface photon estimate at the edges of a room (surface_coverage.h):
// a closed diffuse room 4 wide lit by a point light, no medium, seen from
// inside, rendered by transient_beams with a large surface kernel (radius
// 0.3: about 30 % of what the camera sees lies within r of an edge) and by
// transient_path. Divided by the whole disc, the photons' share of the
// light would be low by 2 / (3 pi) of it over that band (about 6 %, some
// 2-3 % of the image); divided by the disc's area on the surface the sums
// agree within the runs' noise and the ring's quadrature error (2.6 % of that
// loss, below 0.5 % of the image).
#include <gtest/gtest.h>

#include <string>

#include "media_test_util.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::shared_ptr<Scene> room(bool beams) {
  const std::string integrator =
      beams ? R"(<integrator type="transient_beams"><integer name="photon_count" value="40000"/>
        <float name="surface_radius" value="0.3"/><float name="alpha" value="1"/></integrator>)"
            : R"(<integrator type="transient_path"/>)";
  return loadSceneStrict(str(R"(<scene version="3.0.0">)", integrator, R"(
  <shape type="cube"><transform name="to_world"><scale value="2"/></transform>
    <boolean name="flip_normals" value="true"/><bsdf type="diffuse"><float name="reflectance" value="0.7"/></bsdf></shape>
  <emitter type="point"><point name="position" x="0.5" y="1.2" z="-0.5"/><float name="intensity" value="5"/></emitter>
  <sensor type="perspective"><float name="fov" value="100"/>
    <transform name="to_world"><lookat origin="0, 0, 1.9" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value=")",
                             beams ? 4 : 256, R"("/></sampler>
    <film type="transient"><integer name="width" value="12"/><integer name="height" value="12"/>
      <integer name="temporal_bins" value="4"/><float name="start_opl" value="0"/>
      <float name="bin_width_opl" value="6"/><boolean name="write_frames" value="false"/><rfilter type="box"/></film>
  </sensor>
</scene>)"));
}

}  // namespace

TEST(TransientBeamsSurfaceEdges, LargeSurfaceKernelKeepsTheRoomsLight) {
  const std::vector<Mean> beams = imageSums(room(true), "beams-room-edges", 6);
  const std::vector<Mean> path = imageSums(room(false), "path-room-edges", 6);
  expectAgree(beams, path, "room", 0.005);
}
