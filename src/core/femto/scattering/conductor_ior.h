#pragma once
// The complex index of refraction of a conductor as Mitsuba's conductor BSDFs
// take it: a named `material` or explicit `eta` and `k`. Shared by every
// plugin with a metal boundary (conductor, roughconductor), so they accept
// and refuse the same parameters.
#include <string>

#include <femto/math/spectrum.h>

namespace femto {

class Properties;

struct ConductorIOR {
  std::string material = "none";  // the table name, or "custom" for explicit eta and k
  Color3f eta{0.0f}, k{1.0f};     // relative to the exterior; (0, 1) reflects everything
};

/// `material` (a name lookupConductor knows; default "none", a perfect
/// mirror, as in Mitsuba 3) or `eta` and `k` together (<rgb> or <float>),
/// not both; both are then divided by `ext_eta` (Mitsuba 0.6's extEta, the
/// exterior's index: a number or a name from scattering/ior.h; default 1), since
/// the Fresnel equations depend on the index relative to the exterior.
/// Unknown names, a lone eta or k, material with eta/k and negative values
/// are errors naming the parameter's file:line.
ConductorIOR conductorIORFromProperties(const Properties& props);

}  // namespace femto
