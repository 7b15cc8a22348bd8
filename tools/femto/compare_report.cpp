#include "compare_report.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <femto/core/flat_json.h>

namespace femto::cli {
namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

struct MetricRow {
  const char* label;   // in the table
  const char* key;     // in the JSON
  double ErrorMetrics::*field;
};
const MetricRow MetricRows[] = {
    {"MSE", "mse", &ErrorMetrics::mse},
    {"relMSE", "relmse", &ErrorMetrics::relMse},
    {"MAE", "mae", &ErrorMetrics::mae},
    {"max error", "max_error", &ErrorMetrics::maxError},
};

void writeMetricsObject(std::ostream& os, const ErrorMetrics& m, bool withPsnr) {
  os << "{";
  for (const MetricRow& row : MetricRows) os << jsonQuote(row.key) << ": " << jsonNumber(m.*row.field) << ", ";
  if (withPsnr) os << "\"psnr\": " << jsonNumber(psnr(m.mse, m.referencePeak)) << ", ";
  os << "\"reference_peak\": " << jsonNumber(m.referencePeak) << ", \"count\": " << m.count << "}";
}

void writeSeries(std::ostream& os, const char* key, size_t n, const std::function<double(size_t)>& value) {
  os << "    " << jsonQuote(key) << ": [";
  for (size_t i = 0; i < n; ++i) os << (i ? ", " : "") << jsonNumber(value(i));
  os << "]";
}

}  // namespace

void printComparisonTable(std::ostream& os, const Comparison& c) {
  os << "reference  " << c.reference.string() << "\ntest       " << c.test.string() << "\ncompared   ";
  if (c.transient) {
    os << c.width << "x" << c.height << " volume, bins " << c.binBegin << ":" << c.binEnd << " of " << c.bins;
    if (c.grid)
      os << " (OPL " << number(c.grid->start + c.binBegin * c.grid->binWidth) << " to "
         << number(c.grid->start + c.binEnd * c.grid->binWidth) << ")";
  } else {
    os << c.width << "x" << c.height << " image";
  }
  os << ", " << c.pixels << " pixels x " << c.channels << " channels, epsilon " << number(c.epsilon) << "\n\n";
  auto cell = [](const std::string& s, size_t w) { return s + std::string(s.size() < w ? w - s.size() : 1, ' '); };
  os << cell("metric", 12) << cell(c.transient ? "volume" : "image", 14) << (c.transient ? "time integral" : "") << "\n";
  for (const MetricRow& row : MetricRows) {
    os << cell(row.label, 12) << cell(number(c.metrics.*row.field), 14);
    if (c.transient) os << number(c.integral.*row.field);
    os << "\n";
  }
  if (!c.transient)
    os << cell("PSNR", 12) << number(psnr(c.metrics.mse, c.metrics.referencePeak)) << " dB (peak "
       << number(c.metrics.referencePeak) << ")\n";
}

void writeComparisonJson(std::ostream& os, const Comparison& c) {
  os << "{\n  \"reference\": " << jsonQuote(c.reference.string()) << ",\n  \"test\": " << jsonQuote(c.test.string())
     << ",\n  \"kind\": " << (c.transient ? "\"volume\"" : "\"image\"") << ",\n  \"width\": " << c.width
     << ",\n  \"height\": " << c.height << ",\n  \"channels\": " << c.channels << ",\n  \"pixels\": " << c.pixels
     << ",\n  \"epsilon\": " << jsonNumber(c.epsilon) << ",\n  \"metrics\": ";
  writeMetricsObject(os, c.metrics, !c.transient);
  if (c.transient) {
    os << ",\n  \"bins\": " << c.bins << ",\n  \"bin_range\": [" << c.binBegin << ", " << c.binEnd << "]";
    if (c.grid)
      os << ",\n  \"start_opl\": " << jsonNumber(c.grid->start) << ",\n  \"bin_width_opl\": "
         << jsonNumber(c.grid->binWidth);
    os << ",\n  \"time_integral\": ";
    writeMetricsObject(os, c.integral, false);
    const size_t n = c.perBin.size();
    os << ",\n  \"per_bin\": {\n";
    writeSeries(os, "bin", n, [&](size_t i) { return double(c.binBegin + int(i)); });
    for (const MetricRow& row : MetricRows) {
      os << ",\n";
      writeSeries(os, row.key, n, [&](size_t i) { return c.perBin[i].*row.field; });
    }
    os << "\n  }";
  }
  os << "\n}\n";
}

}  // namespace femto::cli
