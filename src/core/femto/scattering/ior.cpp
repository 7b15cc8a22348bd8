#include <femto/scattering/ior.h>

#include <array>
#include <utility>

#include <femto/core/properties.h>
#include <femto/core/spelling.h>

namespace femto {
namespace {

// Names as in Mitsuba's table (0.6 and 3); values at the sodium D line
// (~589 nm) from standard references (CRC Handbook of Chemistry and Physics,
// refractiveindex.info, Schott glass catalogue for BK7).
constexpr std::array<std::pair<std::string_view, float>, 23> IORs = {{
    {"vacuum", 1.0f},
    {"helium", 1.000036f},
    {"hydrogen", 1.000132f},
    {"air", 1.000277f},
    {"carbon dioxide", 1.00045f},
    {"water", 1.3330f},
    {"acetone", 1.36f},
    {"ethanol", 1.361f},
    {"carbon tetrachloride", 1.461f},
    {"glycerol", 1.4729f},
    {"benzene", 1.501f},
    {"silicone oil", 1.52045f},
    {"bromine", 1.661f},
    {"water ice", 1.31f},
    {"fused quartz", 1.458f},
    {"pyrex", 1.470f},
    {"acrylic glass", 1.49f},
    {"polypropylene", 1.49f},
    {"bk7", 1.5046f},
    {"sodium chloride", 1.544f},
    {"amber", 1.55f},
    {"pet", 1.5750f},
    {"diamond", 2.419f},
}};

}  // namespace

std::optional<float> lookupIOR(std::string_view name) {
  for (const auto& [n, v] : IORs)
    if (n == name) return v;
  return std::nullopt;
}

std::vector<std::string> knownIORNames() {
  std::vector<std::string> out;
  for (const auto& entry : IORs) out.emplace_back(entry.first);
  return out;
}

float iorFromProperties(const Properties& props, const std::string& name, float def) {
  if (!props.has(name)) return def;
  if (props.type(name) == Properties::Type::String) {
    std::string value = props.getString(name);
    if (auto ior = lookupIOR(value)) return *ior;
    props.raise(name, str("unknown material \"", value, "\"", didYouMean(value, knownIORNames()),
                          "; give a number or one of the named materials"));
  }
  return props.getFloatIn(name, Range::positive(), "an index of refraction");
}

}  // namespace femto
