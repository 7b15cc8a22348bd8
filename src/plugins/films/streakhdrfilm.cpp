// Mitsuba 2's transient film (`streakhdrfilm`, the mitransient of Mitsuba 2
// days): femto's `transient` film under that film's names, with its defaults,
// so those scenes load unchanged. Time is optical path length, as there.
//
// | name                      | type    | default | meaning                                          |
// |---------------------------|---------|---------|--------------------------------------------------|
// | width, height, crop_*     | integer | 768x576 | as hdrfilm                                       |
// | time (num_bins)           | integer | 1000    | number of time bins (femto: temporal_bins)       |
// | exposure_time (bin_width_opl) | float | 1     | OPL covered by one bin (femto: bin_width_opl)    |
// | time_offset (start_opl)   | float   | 0       | OPL at the start of bin 0 (femto: start_opl)     |
// | <rfilter name="tfilter">  | rfilter | box     | time filter over bins: box (radius 0.5), tent, gaussian |
// | (other nested rfilter)    | rfilter | gaussian | pixel filter (Mitsuba 2's default; any filter)     |
// | high_quality_edges, file_format, pixel_format, component_format | | | as hdrfilm |
//
// Everything else (complete_steady, write_volume, write_frames, start_time /
// bin_width_time in seconds) is as for `transient`. Giving a name and its
// newer alias (time and num_bins) is an error.
#include <femto/core/plugin.h>
#include <femto/film/transient_film.h>

namespace femto {

class StreakHdrFilm final : public TransientFilm {
 public:
  explicit StreakHdrFilm(const Properties& props) : TransientFilm(props, spelling()) {
    // hdrfilm's output options: femto writes float32 EXR (+ PNG) and the
    // .npy volume whatever they say.
    props.getString("file_format", "openexr");
    props.getString("pixel_format", "rgb");
    props.getString("component_format", "float16");
  }

 private:
  static TimeAxisSpelling spelling() {
    TimeAxisSpelling s;
    s.bins = "time";
    s.binsAlias = "num_bins";
    s.defaultPixelFilter = "gaussian";  // Mitsuba 2's films'
    s.binWidth = "exposure_time";
    s.binWidthAlias = "bin_width_opl";
    s.start = "time_offset";
    s.startAlias = "start_opl";
    s.defaultBins = 1000;
    s.defaultBinWidth = 1.0;
    s.nestedTimeFilter = true;
    return s;
  }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::StreakHdrFilm, Film, "streakhdrfilm", "Mitsuba 2 transient (streak) film, femto's transient film")
