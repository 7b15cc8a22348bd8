#include "parse_values.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include <femto/base/error.h>

namespace femto::xml {
namespace {

std::string_view trim(std::string_view s) {
  size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return {};
  size_t e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

/// Split on commas and whitespace, dropping empty pieces.
std::vector<std::string_view> splitList(std::string_view text) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ',' || std::isspace(static_cast<unsigned char>(text[i])))) ++i;
    size_t start = i;
    while (i < text.size() && text[i] != ',' && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > start) out.push_back(text.substr(start, i - start));
  }
  return out;
}

/// Mean of the piecewise-linear interpolant of `s` over [a, b] (trapezoid rule on a fine grid
/// that contains every sample inside the band, so it is exact for piecewise-linear data).
double bandAverage(const std::vector<std::pair<double, double>>& s, double a, double b) {
  auto valueAt = [&](double x) {
    if (x <= s.front().first) return s.front().second;
    if (x >= s.back().first) return s.back().second;
    auto hi = std::lower_bound(s.begin(), s.end(), x, [](const auto& p, double v) { return p.first < v; });
    auto lo = hi - 1;
    double t = (x - lo->first) / (hi->first - lo->first);
    return lo->second + t * (hi->second - lo->second);
  };
  std::vector<double> xs{a, b};
  for (const auto& p : s)
    if (p.first > a && p.first < b) xs.push_back(p.first);
  std::sort(xs.begin(), xs.end());
  double integral = 0;
  for (size_t i = 1; i < xs.size(); ++i) integral += 0.5 * (valueAt(xs[i - 1]) + valueAt(xs[i])) * (xs[i] - xs[i - 1]);
  return integral / (b - a);
}

}  // namespace

double parseFloat(std::string_view text) {
  std::string_view t = trim(text);
  std::string_view digits = !t.empty() && t.front() == '+' ? t.substr(1) : t;
  double v = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size())
    throw Error(str("expected a number, got '", std::string(text), "'"));
  return v;
}

int64_t parseInteger(std::string_view text) {
  std::string_view t = trim(text);
  std::string_view digits = !t.empty() && t.front() == '+' ? t.substr(1) : t;
  int64_t v = 0;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size())
    throw Error(str("expected an integer, got '", std::string(text), "'"));
  return v;
}

// Mitsuba 3 lower-cases the value before comparing, so scenes written from
// Python (value="True"/"False") load there; Mitsuba 0.6 takes the same two words.
bool parseBoolean(std::string_view text) {
  std::string lower(trim(text));
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "true") return true;
  if (lower == "false") return false;
  throw Error(str("expected \"true\" or \"false\" (any case), got '", std::string(text), "'"));
}

std::vector<double> parseNumberList(std::string_view text) {
  std::vector<double> out;
  for (auto piece : splitList(text)) out.push_back(parseFloat(piece));
  return out;
}

Vec3f parseVector3(std::string_view text) {
  auto v = parseNumberList(text);
  if (v.size() != 3) throw Error(str("expected three numbers, got '", std::string(text), "'"));
  return Vec3f(float(v[0]), float(v[1]), float(v[2]));
}

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

Color3f srgbToLinear(const Color3f& c) { return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b)}; }

namespace {
Color3f parseHexColor(std::string_view t) {
  auto hexDigits = t.substr(1);
  unsigned value = 0;
  auto [end, ec] = std::from_chars(hexDigits.data(), hexDigits.data() + hexDigits.size(), value, 16);
  if (hexDigits.size() != 6 || ec != std::errc() || end != hexDigits.data() + hexDigits.size())
    throw Error(str("expected a colour like \"#ff8000\", got '", std::string(t), "'"));
  Color3f encoded(float((value >> 16) & 0xff) / 255.0f, float((value >> 8) & 0xff) / 255.0f, float(value & 0xff) / 255.0f);
  return srgbToLinear(encoded);
}

Color3f parseColorNumbers(std::string_view text) {
  auto v = parseNumberList(text);
  if (v.size() == 1) return Color3f(float(v[0]));
  if (v.size() == 3) return Color3f(float(v[0]), float(v[1]), float(v[2]));
  throw Error(str("expected one or three numbers, got '", std::string(text), "'"));
}
}  // namespace

Color3f parseRgb(std::string_view text) {
  std::string_view t = trim(text);
  if (!t.empty() && t.front() == '#') return parseHexColor(t);
  return parseColorNumbers(t);
}

Color3f parseSrgb(std::string_view text) {
  std::string_view t = trim(text);
  if (!t.empty() && t.front() == '#') return parseHexColor(t);
  return srgbToLinear(parseColorNumbers(t));
}

Color3f parseSpectrum(std::string_view text) {
  if (text.find(':') == std::string_view::npos) {
    auto v = parseNumberList(text);
    if (v.size() != 1)
      throw Error(str("expected one number or \"wavelength:value\" pairs, got '", std::string(text), "'"));
    return Color3f(float(v[0]));
  }
  std::vector<std::pair<double, double>> samples;
  for (auto piece : splitList(text)) {
    size_t colon = piece.find(':');
    if (colon == std::string_view::npos)
      throw Error(str("expected \"wavelength:value\", got '", std::string(piece), "'"));
    double lambda = parseFloat(piece.substr(0, colon));
    if (!samples.empty() && lambda <= samples.back().first)
      throw Error(str("wavelengths must increase, got ", lambda, " after ", samples.back().first));
    samples.emplace_back(lambda, parseFloat(piece.substr(colon + 1)));
  }
  return spectrumToRgb(samples);
}

Color3f spectrumToRgb(const std::vector<std::pair<double, double>>& samples) {
  if (samples.empty()) return Color3f(0.0f);
  return Color3f(float(bandAverage(samples, 600, 700)), float(bandAverage(samples, 500, 600)),
                 float(bandAverage(samples, 400, 500)));
}

}  // namespace femto::xml
