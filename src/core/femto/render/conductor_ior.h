#pragma once
// The complex index of refraction of a conductor as Mitsuba's conductor BSDFs
// take it: a named `material` or explicit `eta` and `k`. Shared by every
// plugin with a metal boundary (conductor, roughconductor).
#include <femto/render/spectrum.h>

namespace femto {

class Properties;

struct ConductorIOR {
  Color3f eta{0.0f}, k{1.0f};  // relative to the exterior; (0, 1) reflects everything
};

/// `material` (a name lookupConductor knows; default "none", a perfect
/// mirror, as in Mitsuba 3) or `eta` and `k` (<rgb> or <float>; defaults 0
/// and 1), not both. Unknown names, both forms together and negative values
/// are errors naming the parameter's file:line.
ConductorIOR conductorIORFromProperties(const Properties& props);

}  // namespace femto
