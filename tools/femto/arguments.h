#pragma once
// Parsing of the structured command-line values (-D name=value, --resolution WxH).
// Errors are femto::Error sentences naming the option and the bad value.
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <femto/math/vector.h>

namespace femto::cli {

/// "-D name=value" arguments into a map; a name given twice keeps the last value.
std::map<std::string, std::string> parseDefines(const std::vector<std::string>& defines);
/// CLI11 check for counts (threads, samples): a whole number >= 1.
extern const CLI::Validator PositiveInteger;

/// "640x480" -> (640, 480); both positive.
Point2i parseResolution(const std::string& text);

}  // namespace femto::cli
