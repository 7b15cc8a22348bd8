#pragma once
// The fog cube the time_splitting and time_gating tests of both transient
// integrators render: a unit-half-size cube of homogeneous fog lit from
// inside by a point light, a diffuse floor inside it, a camera outside, a
// transient film of 12x12 pixels and bins of 0.25 OPL (from OPL 3 with
// observer time, 0 without, plus `firstBin` bins); and the late bins' noise
// those tests compare.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <femto/base/error.h>

#include "transient_agreement_util.h"

namespace femto::test {

struct FogCube {
  float sigmaT, albedo;
  bool observerTime;
};

/// Thin, thick, and thick without observer time.
inline const FogCube FogCubes[] = {{0.5f, 0.8f, true}, {3.0f, 0.95f, true}, {3.0f, 0.95f, false}};

/// The scene, with `integrator` (an <integrator> element: `c`'s observer
/// time is added to it before its closing tag) and `spp` camera samples.
inline std::string fogCubeScene(const FogCube& c, std::string integrator, int spp, int firstBin = 0, int bins = 24) {
  const std::string close = "</integrator>";
  integrator.insert(integrator.rfind(close),
                    str(R"(<boolean name="observer_time" value=")", c.observerTime ? "true" : "false", R"("/>)"));
  return str(R"(<scene version="3.0.0">)", integrator, R"(
  <medium id="fog" type="homogeneous"><float name="sigma_t" value=")", c.sigmaT, R"("/>
    <float name="albedo" value=")", c.albedo, R"("/></medium>
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.95"/><rotate x="1" angle="-90"/><translate y="-0.95"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.7"/></bsdf>
  </shape>
  <emitter type="point"><point name="position" x="0.2" y="0.3" z="-0.1"/><float name="intensity" value="3"/></emitter>
  <sensor type="perspective"><float name="fov" value="35"/>
    <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value=")", spp, R"("/></sampler>
    <film type="transient"><integer name="width" value="12"/><integer name="height" value="12"/>
      <integer name="temporal_bins" value=")", bins, R"("/><float name="start_opl" value=")",
             (c.observerTime ? 3.0 : 0.0) + 0.25 * firstBin, R"("/><float name="bin_width_opl" value="0.25"/><rfilter type="box"/></film>
  </sensor>
</scene>)");
}

/// The late half of the bins' summed squared relative standard error
/// (imageSums: the last entry, the steady image, left out).
inline double lateNoise(const std::vector<Mean>& sums) {
  double n = 0.0;
  for (size_t b = (sums.size() - 1) / 2; b + 1 < sums.size(); ++b)
    n += std::pow(sums[b].standardError() / std::max(sums[b].mean(), 1e-12), 2.0);
  return n;
}

}  // namespace femto::test
