#pragma once
// A minimal JSON reader/writer for small, flat metadata files (the sidecar of
// a transient volume, femto compare's reports): one object whose values are
// numbers, strings, booleans, null or arrays of numbers. Not a general JSON
// library: nested objects are refused with a clear error, which is all these
// files need and keeps the project free of a JSON dependency.
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace femto {

using FlatJsonValue = std::variant<std::nullptr_t, bool, double, std::string, std::vector<double>>;
using FlatJson = std::map<std::string, FlatJsonValue>;

/// Parse `text`; errors are femto::Error naming `source` (a file name) and the line.
FlatJson parseFlatJson(const std::string& text, const std::string& source);

/// `s` as a JSON string literal, quotes included.
std::string jsonQuote(const std::string& s);
/// `v` as a JSON number (the shortest text that reads back exactly);
/// NaN and infinities, which JSON cannot hold, become null.
std::string jsonNumber(double v);

}  // namespace femto
