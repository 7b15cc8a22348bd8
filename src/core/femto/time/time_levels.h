#pragma once
// Roulette and splitting against a transient film's time profile: the
// weight window both transient integrators use (time_splitting). Adjoint-
// driven Russian roulette and splitting (Vorba and Krivanek 2016, "Adjoint-
// driven Russian roulette and splitting in light transport simulation"),
// with the bins a path (or photon) can still reach in place of the pixel's
// value. Derivation and measurements: docs/design/transient-path.md,
// "Splitting against time".
#include <algorithm>
#include <cmath>
#include <vector>

#include <femto/time/time_grid.h>

namespace femto {

/// time_splitting's weight window over the time axis from OPL 0 (or the
/// window's start, if earlier) to the window's end, in the film's OPL: per
/// bin of that axis, the level a path's throughput is compared with there,
/// the mean of the profile over the bins from there to the end (what the
/// path can still reach) over the largest such mean, clamped to [1/64, 1]
/// (never more roulette than Mitsuba's rule; at most 64 times its survival),
/// and 1 up to the bin of that largest mean. The axis starts at 0, not at the
/// window, so a window's render rations its paths as a render of a longer
/// window does over the same times. Empty: no profile.
struct TimeLevels {
  /// At most this many copies at one vertex, and this many in all of one
  /// camera sample's path (or one emitted photon's).
  static constexpr int MaxSplit = 8;
  static constexpr int MaxSplitProduct = 16;
  /// The pilot's bins at most, and its camera samples: a quarter of one
  /// pass's, within these bounds (a small render does not pay more for its
  /// pilot than for itself).
  static constexpr int PilotBins = 4096;
  static constexpr int MinPilotSamples = 256, MaxPilotSamples = 4096;
  static int pilotSamples(double passSamples) {
    return int(std::clamp(passSamples / 4.0, double(MinPilotSamples), double(MaxPilotSamples)));
  }
  /// How many copies a path (or photon) whose throughput relative to the
  /// level is `ratio` splits into (1: none), given the product of its earlier
  /// splits.
  static int splitCount(float ratio, int splitProduct) {
    return int(std::min({ratio, float(MaxSplit), float(MaxSplitProduct / std::max(splitProduct, 1))}));
  }

  TimeGrid axis;
  double windowStart = 0.0;  // the film's grid start (a camera ray's grid is shifted by its time origin)
  std::vector<float> level;

  /// The pilot's axis for a film window: at most `maxBins` bins, none narrower than the window's.
  static TimeGrid pilotAxis(const TimeGrid& window, int maxBins) {
    TimeGrid axis;
    axis.start = std::min(0.0, window.start);
    const double span = window.end() - axis.start;
    axis.bins = int(std::clamp(std::ceil(span / window.binWidth), 1.0, double(maxBins)));
    axis.binWidth = span / axis.bins;
    return axis;
  }
  static TimeLevels fromProfile(const std::vector<double>& profile, const TimeGrid& axis, double windowStart) {
    TimeLevels t;
    const size_t bins = profile.size();
    if (bins == 0) return t;
    std::vector<double> tail(bins);
    double sum = 0.0;
    for (size_t k = bins; k-- > 0;) tail[k] = (sum += std::max(profile[k], 0.0)) / double(bins - k);
    const size_t peak = size_t(std::max_element(tail.begin(), tail.end()) - tail.begin());
    if (!(tail[peak] > 0.0) || !std::isfinite(tail[peak])) return t;
    t.axis = axis;
    t.windowStart = windowStart;
    t.level.resize(bins);
    for (size_t k = 0; k < bins; ++k)
      t.level[k] = k <= peak ? 1.0f : float(std::clamp(tail[k] / tail[peak], 1.0 / 64.0, 1.0));
    return t;
  }
  /// The level at OPL `opl` of a camera ray whose film grid is `grid`: 1
  /// past the window's end too, where a path (traced on for the steady image,
  /// complete_steady) reaches no bin.
  float at(const TimeGrid& grid, double opl) const { return atFilm(opl - (grid.start - windowStart)); }
  /// The level at the film's OPL `opl` (a photon's: light that left the
  /// emitter and has not reached the camera yet lands in the film later).
  float atFilm(double opl) const {
    if (level.empty()) return 1.0f;
    const double k = std::floor((opl - axis.start) / axis.binWidth);
    return k < 0.0 || k >= double(level.size()) ? 1.0f : level[size_t(k)];
  }
};

}  // namespace femto
