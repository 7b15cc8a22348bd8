#pragma once
// The time axis of a transient film. Time is measured as optical path length
// (OPL = c * t, scene units; a scene in metres has OPL in metres): light that
// travels distance d through a medium of refractive index eta adds eta * d.
// A film with bins == 0 is steady (no time axis).
#include <cmath>

namespace femto {

/// Speed of light in vacuum, m/s (to convert seconds <-> OPL in metres).
inline constexpr double SpeedOfLight = 299792458.0;

struct TimeGrid {
  double start = 0.0;     // OPL at the start of bin 0
  double binWidth = 1.0;  // OPL covered by one bin
  int bins = 0;           // number of bins; 0 = steady film

  bool isTransient() const { return bins > 0; }
  double end() const { return start + binWidth * bins; }
  /// Bin containing `opl` ([start + i w, start + (i+1) w)), or -1 outside the window.
  int binOf(double opl) const {
    if (!(opl >= start) || !(opl < end())) return -1;
    int i = int((opl - start) / binWidth);
    return i < bins ? i : bins - 1;
  }
};

}  // namespace femto
