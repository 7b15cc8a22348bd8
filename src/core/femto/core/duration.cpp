#include <femto/core/duration.h>

#include <cmath>
#include <cstdlib>

#include <femto/base/error.h>

namespace femto {

double parseDuration(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  const std::string unit(end == begin ? "" : end);
  double scale = 0.0;
  if (unit.empty() || unit == "s") scale = 1.0;
  else if (unit == "m" || unit == "min") scale = 60.0;
  else if (unit == "h") scale = 3600.0;
  // strtod also reads "inf", "nan" and hex; only plain positive numbers are durations.
  const bool plain = end != begin && (std::isdigit((unsigned char)text[0]) || text[0] == '.');
  if (!plain || scale == 0.0 || !(value > 0.0) || !std::isfinite(value))
    throw Error(str("expected a duration > 0 such as 30s, 5m, 1.5h or 90 (seconds), got \"", text, "\""));
  return value * scale;
}

}  // namespace femto
