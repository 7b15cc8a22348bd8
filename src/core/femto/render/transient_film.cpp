#include <femto/render/transient_film.h>

#include <cmath>

#include <femto/core/error.h>

namespace femto {
namespace {

/// The time window, from exactly one of its two spellings: optical path
/// length (mitransient's transient_hdr_film names) or seconds.
TimeGrid readTimeGrid(const Properties& props) {
  TimeGrid grid;
  int64_t bins = props.getInt("temporal_bins");
  if (bins < 1 || bins > (1 << 20)) props.raise("temporal_bins", str("must be in [1, 1048576], got ", bins));
  grid.bins = int(bins);
  bool opl = props.has("start_opl") || props.has("bin_width_opl");
  bool seconds = props.has("start_time") || props.has("bin_width_time");
  if (opl && seconds)
    props.raise(props.has("start_time") ? "start_time" : "bin_width_time",
                "give the time window either in optical path length (start_opl, bin_width_opl) or in seconds "
                "(start_time, bin_width_time), not both");
  if (!opl && !seconds)
    throw Error(props.location(), "transient film: missing parameter \"bin_width_opl\" (or \"bin_width_time\" in seconds)");
  const char* startName = opl ? "start_opl" : "start_time";
  const char* widthName = opl ? "bin_width_opl" : "bin_width_time";
  // Seconds become OPL in metres: the scene's units are taken to be metres.
  double scale = opl ? 1.0 : SpeedOfLight;
  grid.start = double(props.getFloat(startName, 0.0f)) * scale;
  grid.binWidth = double(props.getFloat(widthName)) * scale;
  if (!std::isfinite(grid.start)) props.raise(startName, "must be finite");
  if (!(grid.binWidth > 0.0) || !std::isfinite(grid.binWidth))
    props.raise(widthName, str("must be positive, got ", props.getFloat(widthName)));
  return grid;
}

TimeFilter readTimeFilter(const Properties& props) {
  std::string type = props.getString("time_filter", "box");
  if (type == "box") return TimeFilter::box();
  if (type != "tent" && type != "gaussian")
    props.raise("time_filter", str("expected \"box\", \"tent\" or \"gaussian\", got \"", type, "\""));
  float width = props.getFloat("time_filter_width", type == "tent" ? 1.0f : 0.5f);
  if (!(width > 0.0f) || !std::isfinite(width)) props.raise("time_filter_width", str("must be positive (bins), got ", width));
  return type == "tent" ? TimeFilter::tent(width) : TimeFilter::gaussian(width);
}

}  // namespace

TransientFilm::TransientFilm(const Properties& props)
    : Film(props, "box"),
      deposit_(readTimeGrid(props), readTimeFilter(props), props.getBool("complete_steady", false)) {
  // Tiles are written out as soon as they are done, so they must not share
  // pixels: a filter reaching past the pixel a sample falls in would need the
  // neighbouring tiles too (see docs/transient-film.md).
  if (filter()->radius() > 0.5f)
    throw Error(props.location(), str("transient film: the pixel reconstruction filter has radius ", filter()->radius(),
                                      " pixels; transient films stream non-overlapping tiles to disk and need "
                                      "<rfilter type=\"box\"/> (radius <= 0.5)"));
  writeVolume_ = props.getBool("write_volume", true);
  writeFrames_ = props.getBool("write_frames", true);
}

TransientFilm::OutputPaths TransientFilm::outputPaths(const std::filesystem::path& path) const {
  std::filesystem::path base = path;
  base.replace_extension();
  auto with = [&](const std::string& suffix) { return std::filesystem::path(base.string() + suffix); };
  return {with(".npy"), with(".exr"), with("_before.exr"), with("_after.exr"), with("_frames")};
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
