#pragma once
// Parsing of the structured command-line values (-D name=value, --resolution WxH).
// Errors are UsageError sentences naming the option and the bad value.
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <femto/math/vector.h>

#include <femto/base/error.h>

namespace femto::cli {

/// A malformed command line (docs/cli.md: usage errors exit 2, failed
/// renders 1): thrown by the parsers of structured option values.
class UsageError : public Error {
 public:
  using Error::Error;
};

/// "-D name=value" arguments into a map; a name given twice keeps the last value.
std::map<std::string, std::string> parseDefines(const std::vector<std::string>& defines);
/// CLI11 check for counts (threads, samples): a whole number >= 1.
extern const CLI::Validator PositiveInteger;

/// "640x480" -> (640, 480); both positive.
Point2i parseResolution(const std::string& text);

}  // namespace femto::cli
