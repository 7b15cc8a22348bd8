#include "arguments.h"

#include <charconv>

#include <femto/base/error.h>

namespace femto::cli {
namespace {

bool parsePositive(std::string_view text, int& value) {
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && value > 0;
}

}  // namespace

const CLI::Validator PositiveInteger(
    [](std::string& text) -> std::string {
      int value = 0;
      return parsePositive(text, value) ? std::string() : "expected a whole number >= 1, got \"" + text + '"';
    },
    "");

std::map<std::string, std::string> parseDefines(const std::vector<std::string>& defines) {
  std::map<std::string, std::string> result;
  for (const std::string& define : defines) {
    size_t eq = define.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError(str("-D expects name=value, got \"", define, "\""));
    result[define.substr(0, eq)] = define.substr(eq + 1);
  }
  return result;
}

Point2i parseResolution(const std::string& text) {
  size_t x = text.find_first_of("xX");
  int width = 0, height = 0;
  if (x == std::string::npos || !parsePositive(std::string_view(text).substr(0, x), width) ||
      !parsePositive(std::string_view(text).substr(x + 1), height))
    throw UsageError(str("--resolution expects WIDTHxHEIGHT with positive integers (e.g. 640x480), got \"", text, "\""));
  return Point2i(width, height);
}

}  // namespace femto::cli
