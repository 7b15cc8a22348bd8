#include <femto/scattering/conductor_ior.h>

#include <femto/core/properties.h>
#include <femto/core/spelling.h>
#include <femto/scattering/fresnel.h>
#include <femto/scattering/ior.h>

namespace femto {
namespace {

/// A non-negative colour parameter (eta or k), with file:line on error.
Color3f nonNegativeColor(const Properties& props, const std::string& name) {
  Color3f c = props.getColor(name);
  if (!c.isValid()) props.raise(name, str("must not be negative, got ", c));
  return c;
}

/// The optical constants before the exterior's index is divided out.
ConductorIOR readOpticalConstants(const Properties& props) {
  ConductorIOR ior;
  const bool hasEta = props.has("eta"), hasK = props.has("k");
  if (hasEta || hasK) {
    if (props.has("material")) props.raise("material", "give either a material name or eta and k, not both");
    if (!hasEta || !hasK) props.raise(hasEta ? "eta" : "k", "eta and k must be given together");
    ior.material = "custom";
    ior.eta = nonNegativeColor(props, "eta");
    ior.k = nonNegativeColor(props, "k");
    return ior;
  }
  ior.material = props.getString("material", "none");
  auto constants = lookupConductor(ior.material);
  if (!constants)
    props.raise("material", str("unknown conductor \"", ior.material, "\"",
                                didYouMean(ior.material, knownConductorNames()), "; give eta and k for other metals"));
  ior.eta = constants->first;
  ior.k = constants->second;
  return ior;
}

}  // namespace

ConductorIOR conductorIORFromProperties(const Properties& props) {
  ConductorIOR ior = readOpticalConstants(props);
  const float extEta = iorFromProperties(props, "ext_eta", 1.0f);
  ior.eta = ior.eta / extEta;
  ior.k = ior.k / extEta;
  return ior;
}

}  // namespace femto
