#pragma once
// Named indices of refraction, as Mitsuba's dielectric BSDFs accept them
// (`<string name="int_ior" value="bk7"/>`).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace femto {

class Properties;

/// Refractive index of a named material (Mitsuba's table names, e.g. "bk7",
/// "water", "air"), at about 589 nm; nullopt for unknown names.
std::optional<float> lookupIOR(std::string_view name);
/// The names lookupIOR knows.
std::vector<std::string> knownIORNames();

/// Parameter `name` as an index of refraction: a <float> or a named <string>;
/// `def` when absent. Unknown names and values <= 0 are errors naming file:line.
float iorFromProperties(const Properties& props, const std::string& name, float def);

}  // namespace femto
