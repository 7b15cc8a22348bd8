#include "foreign_plugins.h"

#include <map>

namespace femto::xml {
namespace {

constexpr const char* UseSurfaceOrMedia =
    "use path (surfaces), transient_path (media, time-resolved) or transient_beams (media, photon beams)";

/// Mitsuba's shading-normal wrappers: femto refuses them rather than render
/// the nested BSDF with an unperturbed normal, which would look plausible but
/// wrong.
std::string adviceForForeignBSDF(const std::string& name) {
  if (name != "bumpmap" && name != "normalmap") return "";
  return " (bump and normal mapping perturb the shading frame, which femto's BSDFs do not support yet; remove the "
         "wrapper to render the nested BSDF on the unperturbed surface)";
}

}  // namespace

std::string adviceForForeignPlugin(ObjectKind kind, const std::string& name) {
  if (kind == ObjectKind::BSDF) return adviceForForeignBSDF(name);
  if (kind == ObjectKind::Sensor && name == "nloscapturemeter")
    return " (Mitsuba 2's non-line-of-sight capture meter: use mitransient's nlos_capture_meter, which femto has, "
           "with the transient_nlos_path integrator)";
  if (kind != ObjectKind::Integrator) return "";
  static const std::map<std::string, std::string> advice = {
      {"bdpt", "bidirectional path tracing (Mitsuba's bdpt) is not part of femto"},
      {"vcm", "vertex connection and merging is not part of femto"},
      {"mlt", "Metropolis light transport is not part of femto"},
      {"pssmlt", "primary-sample-space MLT is not part of femto"},
      {"erpt", "energy redistribution path tracing is not part of femto"},
      {"mmlt", "multiplexed MLT is not part of femto"},
      {"ptracer", "particle tracing from the lights (ptracer) is not part of femto"},
      {"vpl", "virtual point lights are not part of femto"},
      {"photonmapper", "surface photon mapping is part of transient_beams only"},
      {"ppm", "progressive photon mapping is part of transient_beams only"},
      {"sppm", "stochastic progressive photon mapping is part of transient_beams only"},
      {"guided_path", "path guiding (Mueller et al. 2017) is not part of femto"},
      {"pathguiding", "path guiding is not part of femto"},
      {"ppg", "practical path guiding is not part of femto"},
      {"guided_volpath", "volumetric path guiding is not part of femto"},
      {"transientnlospath", "Mitsuba 2's NLOS path tracer: use mitransient's name, transient_nlos_path"},
  };
  auto it = advice.find(name);
  if (it == advice.end()) return "";
  return " (" + it->second + "; " + UseSurfaceOrMedia + ")";
}

}  // namespace femto::xml
