// mitransient's name for femto's `transient` film: the same class and
// parameters (temporal_bins, start_opl, bin_width_opl, ...; see
// src/plugins/films/transient.cpp), with mitransient's defaults, so scenes
// written for mitransient load unchanged and render the same window:
//
// | name          | type    | default | meaning (mitransient's TransientHDRFilm) |
// |---------------|---------|---------|------------------------------------------|
// | temporal_bins | integer | 2048    | number of time bins                      |
// | bin_width_opl | float   | 0.003   | OPL covered by one bin (scene units)     |
// | start_opl     | float   | 0       | OPL at the start of bin 0                |
//
// mitransient takes the time filter from the integrator (temporal_filter,
// gaussian_stddev); the scene hands it to this film (docs/coming-from-mitransient.md).
// Its OPL counts from each camera ray's near-clip point, as mitransient's
// (Mitsuba 3's cameras start their rays there): near_clip / cos theta less
// than femto's `transient` film, which counts from the camera.
#include <femto/core/plugin.h>
#include <femto/film/transient_film.h>

namespace femto {

class MitransientHdrFilm final : public TransientFilm {
 public:
  explicit MitransientHdrFilm(const Properties& props) : TransientFilm(props, spelling()) {}

 private:
  static TimeAxisSpelling spelling() {
    TimeAxisSpelling s;
    s.defaultBins = 2048;
    s.defaultBinWidth = 0.003;
    s.nearClipOrigin = true;
    s.defaultPixelFilter = "gaussian";  // Mitsuba 3's films'
    return s;
  }
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::MitransientHdrFilm, Film, "transient_hdr_film", "mitransient name of the transient film")
