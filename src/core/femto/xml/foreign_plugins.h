#pragma once
// Plugins of other renderers that femto does not have, with what to use
// instead: a scene naming one fails with the type, file:line and this advice
// rather than a bare "unknown plugin".
#include <string>

#include <femto/core/object.h>

namespace femto::xml {

/// " (advice)" for a known plugin of Mitsuba 0.6 / 3, mitransient or a
/// research fork that femto does not implement; "" for any other name.
std::string adviceForForeignPlugin(ObjectKind kind, const std::string& name);

}  // namespace femto::xml
