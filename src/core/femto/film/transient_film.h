#pragma once
// A film with a time axis: per pixel an RGB histogram over time of arrival
// (measured as optical path length, see time_grid.h), the steady image (all
// light arriving before the horizon, or all light with complete_steady) and
// the energy that arrived before and after the time window. Rendered only by TransientIntegrators, whose render
// loop streams finished tiles straight to disk (transient_output.h); the
// volume is never held in memory whole. See docs/transient-film.md.
#include <filesystem>
#include <string>

#include <femto/render/film.h>
#include <femto/time/time_deposit.h>
#include <femto/time/time_grid.h>

namespace femto {

/// How a scene names the time axis: femto's `transient` film, mitransient's
/// `transient_hdr_film` and Mitsuba 2's `streakhdrfilm` are one film written
/// three ways (docs/coming-from-mitransient.md).
struct TimeAxisSpelling {
  /// Bin count, bin width and start (in OPL), each under its name and an
  /// older alternative name ("" = none); giving both names is an error.
  const char* bins = "temporal_bins";
  const char* binsAlias = "";
  const char* binWidth = "bin_width_opl";
  const char* binWidthAlias = "";
  const char* start = "start_opl";
  const char* startAlias = "";
  /// Defaults; a negative value makes the parameter required.
  int64_t defaultBins = -1;
  double defaultBinWidth = -1.0;
  /// The time filter as a nested <rfilter name="tfilter"> (Mitsuba 2) rather
  /// than time_filter / time_filter_width.
  bool nestedTimeFilter = false;
  /// Where OPL 0 is on each camera ray: at the sensor's centre of projection
  /// (femto's convention) or, as mitransient counts, at the ray's near-clip
  /// point (near_clip / cos theta from the camera for a perspective one).
  bool nearClipOrigin = false;
  /// The pixel filter when the scene gives none: femto's box, or Mitsuba's gaussian.
  const char* defaultPixelFilter = "box";
};

class TransientFilm : public Film {
 public:
  /// Reads the Film parameters (default rfilter: box; filters wider than one
  /// pixel are refused), temporal_bins, start_opl + bin_width_opl or
  /// start_time + bin_width_time (seconds), time_filter + time_filter_width,
  /// complete_steady, write_volume, write_frames. See src/plugins/films/transient.cpp.
  explicit TransientFilm(const Properties& props, const TimeAxisSpelling& spelling = {});

  /// mitransient gives the time filter to the integrator (temporal_filter,
  /// gaussian_stddev); the scene hands it to the film before rendering.
  /// Refused, naming `where`, when the film gave a different filter itself.
  void useIntegratorTimeFilter(const TimeFilter& filter, const SourceLocation& where) override;
  bool timeResolved() const override { return true; }
  /// The time window: start_opl, bin_width_opl, temporal_bins.
  ParameterValues editableParameters() const override {
    const TimeGrid& g = deposit_.grid();
    return {{"start_opl", {g.start}}, {"bin_width_opl", {g.binWidth}}, {"temporal_bins", {double(g.bins)}}};
  }
  void setParameter(const std::string& name, const std::vector<double>& value) override;

  const TimeGrid& timeGrid() const { return deposit_.grid(); }
  const TimeFilter& timeFilter() const { return deposit_.filter(); }
  const TimeDeposit& timeDeposit() const { return deposit_; }
  /// Does each camera ray's OPL count from its near-clip point (mitransient's
  /// films, TimeAxisSpelling::nearClipOrigin) rather than from the sensor?
  bool nearClipOrigin() const { return nearClipOrigin_; }
  /// Keep the .npy volume (false: it is written to a temporary file for the
  /// frames and removed).
  bool writesVolume() const { return writeVolume_; }
  /// Write one EXR per time bin into <stem>_frames/.
  bool writesFrames() const { return writeFrames_; }

  /// The files a render to `path` produces (only the stem of `path` matters).
  struct OutputPaths {
    std::filesystem::path volume;     // <stem>.npy
    std::filesystem::path steady;     // <stem>.exr (+ <stem>.png preview)
    std::filesystem::path before;     // <stem>_before.exr: energy arriving before the window
    std::filesystem::path after;      // <stem>_after.exr: energy arriving at or after its end
    std::filesystem::path framesDir;  // <stem>_frames/ with frame_00000.exr, ...
  };
  OutputPaths outputPaths(const std::filesystem::path& path) const;
  /// Before rendering: none of the files a render to `path` writes may be a
  /// folder, and the frames folder must be a writable folder (or absent in a
  /// writable one), so that nothing fails only when the frames are written.
  void checkOutputPath(const std::filesystem::path& path) const override;

  /// A transient film is developed by TransientIntegrator::render; a steady
  /// integrator reaching here is an error (it was checked before rendering).
  void develop(const ImageBlock& image, const std::filesystem::path& path) const override;
  std::string defaultExtension() const override { return ".npy"; }
  std::string toString() const override;

 private:
  TimeDeposit deposit_;
  SourceLocation timeFilterGivenAt_;  // empty file: the film's filter is its default
  bool writeVolume_ = true, writeFrames_ = true;
  bool nearClipOrigin_ = false;
};

}  // namespace femto
