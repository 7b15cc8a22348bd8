#pragma once
// Parse stage 5 helpers: the value="" text of <float>, <integer>, <boolean>,
// <rgb>, <spectrum>, ... Errors are femto::Error without a location; the
// caller adds the element's file:line.
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto::xml {

double parseFloat(std::string_view text);      // "expected a number, got 'abc'"
int64_t parseInteger(std::string_view text);   // "expected an integer, got '1.5'"
bool parseBoolean(std::string_view text);      // "true" / "false", any case ("True" from Python)
/// Numbers separated by commas and/or whitespace.
std::vector<double> parseNumberList(std::string_view text);
/// Exactly three numbers ("1, 2, 3" or "1 2 3").
Vec3f parseVector3(std::string_view text);

/// sRGB transfer function decoded to linear (IEC 61966-2-1).
float srgbToLinear(float encoded);
Color3f srgbToLinear(const Color3f& encoded);
/// <rgb value>: one (grey) or three linear values; "#rrggbb" is an 8-bit sRGB
/// colour (Mitsuba 0.6) and is decoded to linear.
Color3f parseRgb(std::string_view text);
/// <srgb value>: like <rgb> but the numbers are sRGB-encoded, decoded to linear.
Color3f parseSrgb(std::string_view text);
/// <spectrum value>: one number (grey), or "λ:value, λ:value, ..." with
/// wavelengths in nm, reduced to RGB by spectrumToRgb.
Color3f parseSpectrum(std::string_view text);
/// Reduce sampled (wavelength nm, value) pairs to RGB as the average of the
/// piecewise-linear spectrum over three bands: blue 400-500 nm, green
/// 500-600 nm, red 600-700 nm (held constant beyond the first/last sample).
/// A constant spectrum maps to the same grey, and reflectances stay in [0, 1].
/// This is a deliberate simplification of CIE-weighted conversion: femto is RGB-only.
Color3f spectrumToRgb(const std::vector<std::pair<double, double>>& samples);

}  // namespace femto::xml
