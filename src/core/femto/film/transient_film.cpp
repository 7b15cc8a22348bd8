#include <femto/film/transient_film.h>

#include <cmath>
#include <limits>

#include <femto/base/error.h>
#include <femto/core/resources.h>
#include <femto/render/rfilter.h>

namespace femto {
namespace {

/// The name a parameter was given under: `name`, or its older `alias` when
/// only that is present (both present is an error naming the alias's line).
std::string spelledName(const Properties& props, const char* name, const char* alias) {
  if (*alias && props.has(alias)) {
    if (props.has(name)) props.raise(alias, str("\"", alias, "\" and \"", name, "\" are one parameter: give one of them"));
    return alias;
  }
  return name;
}

/// The time window, from exactly one of its two forms: optical path length
/// (under the spelling's names) or seconds (start_time, bin_width_time).
TimeGrid readTimeGrid(const Properties& props, const TimeAxisSpelling& spelling) {
  TimeGrid grid;
  const std::string binsName = spelledName(props, spelling.bins, spelling.binsAlias);
  const std::string widthOplName = spelledName(props, spelling.binWidth, spelling.binWidthAlias);
  const std::string startOplName = spelledName(props, spelling.start, spelling.startAlias);
  constexpr int64_t MaxBins = 1 << 20;
  grid.bins = int(spelling.defaultBins > 0 ? props.getInt(binsName, spelling.defaultBins, 1, MaxBins)
                                           : props.getIntIn(binsName, 1, MaxBins));
  bool opl = props.has(startOplName) || props.has(widthOplName);
  bool seconds = props.has("start_time") || props.has("bin_width_time");
  if (opl && seconds)
    props.raise(props.has("start_time") ? "start_time" : "bin_width_time",
                str("give the time window either in optical path length (", startOplName, ", ", widthOplName,
                    ") or in seconds (start_time, bin_width_time), not both"));
  if (!opl && !seconds && spelling.defaultBinWidth <= 0.0)
    throw Error(props.location(), str("transient film: missing parameter \"", widthOplName,
                                      "\" (or \"bin_width_time\" in seconds)"));
  const std::string startName = seconds ? "start_time" : startOplName;
  const std::string widthName = seconds ? "bin_width_time" : widthOplName;
  // Seconds become OPL in metres: the scene's units are taken to be metres.
  double scale = seconds ? SpeedOfLight : 1.0;
  grid.start = double(props.getFloat(startName, 0.0f, Range::finite())) * scale;
  grid.binWidth = spelling.defaultBinWidth > 0.0 && !seconds
                      ? double(props.getFloat(widthName, float(spelling.defaultBinWidth), Range::positive()))
                      : double(props.getFloatIn(widthName, Range::positive())) * scale;
  return grid;
}

/// Mitsuba 2's streak film: a pixel filter used along time, in bins.
TimeFilter timeFilterFromPixelFilter(const ReconstructionFilter& filter, const Properties& props) {
  using Type = ReconstructionFilter::Profile::Type;
  ReconstructionFilter::Profile profile = filter.profile();
  auto refuse = [&](const std::string& why) -> TimeFilter {
    throw Error(props.location("tfilter"), str("<rfilter name=\"tfilter\">: ", why));
  };
  switch (profile.type) {
    case Type::Box:
      // femto's box time filter puts each contribution in its own bin, which
      // is a box of radius half a bin; a wider box has no counterpart.
      if (std::abs(profile.width - 0.5f) > 1e-6f)
        return refuse(str("a box of radius ", profile.width,
                          " bins is not supported: the box time filter is one bin wide (radius 0.5); "
                          "use a tent or gaussian tfilter to spread contributions over neighbouring bins"));
      return TimeFilter::box();
    case Type::Tent: return TimeFilter::tent(profile.width);
    case Type::Gaussian: return TimeFilter::gaussian(profile.width);
    case Type::Other: break;
  }
  return refuse(str(filter.toString(), " has no time-filter counterpart: use box, tent or gaussian"));
}

TimeFilter readTimeFilter(const Properties& props, const TimeAxisSpelling& spelling) {
  if (spelling.nestedTimeFilter && props.has("tfilter")) {
    auto filter = std::dynamic_pointer_cast<ReconstructionFilter>(props.getObject("tfilter"));
    if (!filter) props.raise("tfilter", "must be an <rfilter>");
    return timeFilterFromPixelFilter(*filter, props);
  }
  enum class Kind { Box, Tent, Gaussian };
  const Kind kind = props.getEnum("time_filter", Kind::Box,
                                  {{"box", Kind::Box}, {"tent", Kind::Tent}, {"gaussian", Kind::Gaussian}});
  if (kind == Kind::Box) return TimeFilter::box();
  float width = props.getFloat("time_filter_width", kind == Kind::Tent ? 1.0f : 0.5f, Range::positive(), "bins");
  return kind == Kind::Tent ? TimeFilter::tent(width) : TimeFilter::gaussian(width);
}

/// Where the scene chose the film's time filter (empty when it did not).
SourceLocation timeFilterLocation(const Properties& props, const TimeAxisSpelling& spelling) {
  if (spelling.nestedTimeFilter && props.has("tfilter")) return props.location("tfilter");
  if (props.has("time_filter")) return props.location("time_filter");
  return {};
}

}  // namespace

TransientFilm::TransientFilm(const Properties& props, const TimeAxisSpelling& spelling)
    : Film(props, spelling.defaultPixelFilter, spelling.nestedTimeFilter ? "tfilter" : ""),
      deposit_(readTimeGrid(props, spelling), readTimeFilter(props, spelling), props.getBool("complete_steady", false)),
      timeFilterGivenAt_(timeFilterLocation(props, spelling)),
      nearClipOrigin_(spelling.nearClipOrigin) {
  // A filter reaching past the pixel a sample falls in: tiles carry a border
  // that TransientOutput merges with their neighbours' as they stream.
  // Mitsuba 3's sample_border (0.6: high_quality_edges) lets samples outside
  // the crop window reach its edge pixels through the filter: accepted, not
  // done (edge pixels average the samples inside the window).
  props.getBool("sample_border", false);
  props.getBool("high_quality_edges", false);
  writeVolume_ = props.getBool("write_volume", true);
  // Off by default: 400 per-bin EXRs cost ~0.5-1 s per render (issue 34);
  // `femto frames` writes them from the volume on demand.
  writeFrames_ = props.getBool("write_frames", false);
}

void TransientFilm::setParameter(const std::string& name, const std::vector<double>& value) {
  constexpr double Largest = std::numeric_limits<double>::max();
  TimeGrid grid = deposit_.grid();
  if (name == "start_opl")
    grid.start = editableNumber(toString(), name, value, -Largest, Largest);
  else if (name == "bin_width_opl")
    grid.binWidth = editableNumber(toString(), name, value, std::numeric_limits<double>::min(), Largest);
  else if (name == "temporal_bins")
    grid.bins = int(editableNumber(toString(), name, value, 1.0, double(1 << 28), true));
  else
    return Film::setParameter(name, value);
  deposit_ = TimeDeposit(grid, deposit_.filter(), deposit_.unboundedHorizon());
}

void TransientFilm::useIntegratorTimeFilter(const TimeFilter& filter, const SourceLocation& where) {
  const TimeFilter& own = deposit_.filter();
  if (timeFilterGivenAt_.known() && (own.type() != filter.type() || own.width() != filter.width()))
    throw Error(where, str("the integrator's temporal_filter (", filter.name(), ") differs from the time filter the film gives at ",
                           timeFilterGivenAt_.toString(), " (", own.name(), "): give it in one place"));
  deposit_ = TimeDeposit(deposit_.grid(), filter, deposit_.unboundedHorizon());
}

TransientFilm::OutputPaths TransientFilm::outputPaths(const std::filesystem::path& path) const {
  std::filesystem::path base = path;
  base.replace_extension();
  auto with = [&](const std::string& suffix) { return std::filesystem::path(base.string() + suffix); };
  return {with(".npy"), with(".exr"), with("_before.exr"), with("_after.exr"), with("_frames")};
}

void TransientFilm::checkOutputPath(const std::filesystem::path& path) const {
  const OutputPaths paths = outputPaths(path);
  for (const auto* file : {&paths.volume, &paths.steady, &paths.before, &paths.after})
    if ((file != &paths.volume || writeVolume_) && std::filesystem::is_directory(*file))
      throw Error(str("cannot write \"", file->string(), "\" (for -o \"", path.string(), "\"): it is a folder"));
  if (writeFrames_) requireWritableFolder(paths.framesDir, paths.framesDir, /*makeMissing=*/false);
}

void TransientFilm::develop(const ImageBlock&, const std::filesystem::path&) const {
  throw Error("a transient film can only be rendered by a transient integrator (e.g. transient_path)");
}

std::string TransientFilm::toString() const {
  const TimeGrid& g = timeGrid();
  return str("TransientFilm[size=", size().x, "x", size().y, ", crop=", cropSize().x, "x", cropSize().y, "+",
             cropOffset().x, "+", cropOffset().y, ", bins=", g.bins, ", start_opl=", g.start, ", bin_width_opl=",
             g.binWidth, ", time_filter=", timeFilter().name(), "]");
}

}  // namespace femto
