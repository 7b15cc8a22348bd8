// mitransient's name for femto's `transient` film (same class, same
// parameters: temporal_bins, start_opl, bin_width_opl, ...), so scenes written
// for mitransient load unchanged. See src/plugins/films/transient.cpp.
#include <femto/core/plugin.h>
#include <femto/render/transient_film.h>

FEMTO_EXPORT_PLUGIN(femto::TransientFilm, Film, "transient_hdr_film", "mitransient name of the transient film")
