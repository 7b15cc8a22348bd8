// mitransient's phasor film (src/core/femto/film/phasor_film.h):
//
// | name          | type    | default | meaning (mitransient's PhasorHDRFilm)                         |
// |---------------|---------|---------|---------------------------------------------------------------|
// | wl_mean       | float   | 100     | central wavelength of the frequencies kept (OPL units)        |
// | wl_sigma      | float   | 1000    | their spread: indices mean -+ 3 (nt bw) / (6 wl_sigma)         |
// | temporal_bins | integer | 4096    | nt: the time axis the frequencies are a DFT's of              |
// | bin_width_opl | float   | 0.003   | bw: its bin width (OPL)                                        |
// | start_opl     | float   | 0       | OPL of phase 0                                                |
// | (rfilter)     | rfilter | gaussian| pixel filter (Mitsuba's default)                              |
#include <femto/core/plugin.h>
#include <femto/film/phasor_film.h>

FEMTO_EXPORT_PLUGIN(femto::PhasorFilm, Film, "phasor_hdr_film", "mitransient's phasor film: Fourier coefficients of each pixel's time profile")
