#include <femto/render/conductor_ior.h>

#include <femto/core/properties.h>
#include <femto/core/spelling.h>
#include <femto/render/fresnel.h>

namespace femto {

ConductorIOR conductorIORFromProperties(const Properties& props) {
  ConductorIOR ior;
  std::string material = props.getString("material", "none");
  bool explicitIOR = props.has("eta") || props.has("k");
  if (explicitIOR && material != "none")
    props.raise("material", str("give either \"material\" or \"eta\" and \"k\", not both"));
  if (!explicitIOR) {
    auto named = lookupConductor(material);
    if (!named)
      props.raise("material", str("unknown conductor \"", material, "\"", didYouMean(material, knownConductorNames()),
                                  "; give a known name or \"eta\" and \"k\""));
    ior.eta = named->first;
    ior.k = named->second;
    return ior;
  }
  ior.eta = props.getColor("eta", Color3f(0.0f));
  ior.k = props.getColor("k", Color3f(1.0f));
  auto check = [&](const char* name, const Color3f& value) {
    if (!value.isValid())
      props.raise(name, str("the complex index of refraction needs finite values >= 0, got ", value));
  };
  check("eta", ior.eta);
  check("k", ior.k);
  return ior;
}

}  // namespace femto
