#pragma once
// Durations as people type them ("30s", "5m", "1.5h", "90" = seconds): the
// render's time limit (`femto render --time-limit`, the Python module's
// render(time_limit=...)).
#include <string>

namespace femto {

/// Seconds in `text`: a number > 0, optionally followed by s, m or h. Throws
/// an Error saying what was expected and quoting `text`.
double parseDuration(const std::string& text);

}  // namespace femto
