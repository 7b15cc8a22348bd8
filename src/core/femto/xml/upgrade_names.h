#pragma once
// Parse stage 3: Mitsuba 0.4-0.6 scenes (version < 2) spell parameter names in
// camelCase ("toWorld", "intIOR"); femto, like Mitsuba 3, uses snake_case.
#include <string>
#include <string_view>

#include "xml_node.h"

namespace femto::xml {

/// "toWorld" -> "to_world", "intIOR" -> "int_ior", "cropOffsetX" -> "crop_offset_x":
/// an underscore before an uppercase letter that follows a lowercase letter or
/// a digit, then everything lowercased. snake_case input and one-letter names
/// ("B") are returned unchanged.
std::string camelToSnake(std::string_view name);

/// Rewrite the name="" attributes of every node from a version < 2 file.
/// Nodes from Mitsuba 3 files keep their names.
void upgradeLegacyNames(XmlNode& root);

/// The femto plugin that renders scenes naming Mitsuba plugin `type` for an
/// object with tag `tag`, or `type` itself. Mitsuba's volumetric path tracers
/// ("volpath", 0.6's "volpath_simple", Mitsuba 3's "volpathmis") map to
/// "transient_path", which also renders steady films; Mitsuba 3's
/// differentiable prb, prb_basic, prb_projective map to "path",
/// direct_projective to "direct", prbvolpath to "transient_path". Both dialects.
std::string upgradePluginType(std::string_view tag, const std::string& type);

/// Rewrite the type="" attributes of every node with upgradePluginType. A
/// mapped integrator whose original defaults max_depth to 6 (Mitsuba 3's
/// Python integrators) gets that max_depth when the scene gives none.
void upgradePluginTypes(XmlNode& root);

}  // namespace femto::xml
