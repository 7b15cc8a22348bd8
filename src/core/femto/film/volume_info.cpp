#include <femto/film/volume_info.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <femto/base/error.h>
#include <femto/core/flat_json.h>
#include <femto/image/image_io.h>

namespace femto {
namespace {

constexpr const char* FormatName = "femto transient volume";

double numberField(const FlatJson& json, const std::string& key, const std::filesystem::path& path) {
  auto it = json.find(key);
  if (it == json.end()) throw Error(str("volume sidecar \"", path.string(), "\": missing \"", key, "\""));
  if (const double* v = std::get_if<double>(&it->second)) return *v;
  throw Error(str("volume sidecar \"", path.string(), "\": \"", key, "\" must be a number"));
}

int intField(const FlatJson& json, const std::string& key, const std::filesystem::path& path) {
  double v = numberField(json, key, path);
  if (v != std::floor(v) || v < 0 || v > 1e9)
    throw Error(str("volume sidecar \"", path.string(), "\": \"", key, "\" must be a whole number >= 0, got ", v));
  return int(v);
}

}  // namespace

std::filesystem::path volumeInfoPath(const std::filesystem::path& volume) {
  std::filesystem::path p = volume;
  return p.replace_extension(".json");
}

void writeVolumeInfo(const std::filesystem::path& path, const VolumeInfo& info) {
  std::ostringstream os;
  os << "{\n  \"format\": " << jsonQuote(FormatName) << ",\n  \"version\": 1,\n"
     << "  \"width\": " << info.width << ",\n  \"height\": " << info.height << ",\n  \"bins\": " << info.grid.bins
     << ",\n  \"time_unit\": \"opl\",\n"
     << "  \"start_opl\": " << jsonNumber(info.grid.start) << ",\n"
     << "  \"bin_width_opl\": " << jsonNumber(info.grid.binWidth) << ",\n"
     << "  \"end_opl\": " << jsonNumber(info.grid.end()) << ",\n"
     << "  \"film_width\": " << info.filmSize.x << ",\n  \"film_height\": " << info.filmSize.y << ",\n"
     << "  \"crop\": [" << info.cropOffset.x << ", " << info.cropOffset.y << ", " << info.width << ", " << info.height
     << "],\n  \"time_filter\": " << jsonQuote(info.timeFilter);
  if (const auto& r = info.render) {
    os << ",\n  \"passes\": " << r->passes << ",\n  \"spp_per_pass\": " << r->samplesPerPass
       << ",\n  \"spp\": " << uint64_t(r->passes) * uint64_t(r->samplesPerPass) << ",\n  \"seed\": " << r->seed;
    if (r->timeLimit > 0.0)
      os << ",\n  \"time_limit_seconds\": " << jsonNumber(r->timeLimit) << ",\n  \"time_clock\": "
         << jsonQuote(r->timeClock) << ",\n  \"time_limit_reached\": " << (r->timeLimitReached ? "true" : "false");
  }
  for (const auto& [key, value] : info.extra) os << ",\n  " << jsonQuote(key) << ": " << value;
  os << "\n}\n";
  std::string text = os.str();
  writeAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out.flush()) throw Error(str("cannot write \"", path.string(), "\""));
  });
}

std::optional<VolumeInfo> readVolumeInfo(const std::filesystem::path& volume) {
  std::filesystem::path path = volumeInfoPath(volume);
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream text;
  text << in.rdbuf();
  FlatJson json = parseFlatJson(text.str(), path.string());
  auto format = json.find("format");
  if (format == json.end() || format->second != FlatJsonValue(std::string(FormatName)))
    throw Error(str("\"", path.string(), "\" beside the volume is not a femto volume sidecar (no \"format\": \"",
                    FormatName, "\")"));
  VolumeInfo info;
  info.width = intField(json, "width", path);
  info.height = intField(json, "height", path);
  info.grid.bins = intField(json, "bins", path);
  info.grid.start = numberField(json, "start_opl", path);
  info.grid.binWidth = numberField(json, "bin_width_opl", path);
  if (json.count("film_width")) info.filmSize = {intField(json, "film_width", path), intField(json, "film_height", path)};
  auto crop = json.find("crop");
  if (crop != json.end()) {
    const auto* c = std::get_if<std::vector<double>>(&crop->second);
    if (!c || c->size() != 4) throw Error(str("volume sidecar \"", path.string(), "\": \"crop\" must be [x, y, width, height]"));
    info.cropOffset = {int((*c)[0]), int((*c)[1])};
  }
  if (json.count("passes")) {
    RenderRecord r;
    r.passes = intField(json, "passes", path);
    r.samplesPerPass = intField(json, "spp_per_pass", path);
    r.seed = uint64_t(numberField(json, "seed", path));
    if (json.count("time_limit_seconds")) {
      r.timeLimit = numberField(json, "time_limit_seconds", path);
      if (auto c = json.find("time_clock"); c != json.end())
        if (const auto* text = std::get_if<std::string>(&c->second)) r.timeClock = *text;
      if (auto b = json.find("time_limit_reached"); b != json.end())
        if (const auto* reached = std::get_if<bool>(&b->second)) r.timeLimitReached = *reached;
    }
    info.render = r;
  }
  auto filter = json.find("time_filter");
  if (filter != json.end())
    if (const auto* s = std::get_if<std::string>(&filter->second)) info.timeFilter = *s;
  return info;
}

bool sameTimeWindow(const TimeGrid& a, const TimeGrid& b) {
  auto close = [&](double x, double y) { return std::abs(x - y) <= 1e-6 * std::max({std::abs(x), std::abs(y), a.binWidth}); };
  return a.bins == b.bins && close(a.start, b.start) && close(a.binWidth, b.binWidth);
}

std::string describeTimeWindow(const TimeGrid& grid) {
  return str(grid.bins, " bins of OPL ", grid.binWidth, " from ", grid.start, " to ", grid.end());
}

}  // namespace femto
