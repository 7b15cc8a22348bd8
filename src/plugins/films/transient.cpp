// Transient film: a time-resolved RGB volume per pixel, streamed to disk while
// rendering, plus the steady image and the energy before/after the window.
// Time is optical path length (OPL = c * t, scene units; see
// docs/transient-film.md). Needs a transient integrator (transient_path, ...).
// mitransient's name for the same film is `transient_hdr_film` (a plugin of its own).
//
// | name               | type    | default   | meaning                                                        |
// |--------------------|---------|-----------|----------------------------------------------------------------|
// | width, height      | integer | 768, 576  | film size in pixels                                            |
// | crop_offset_x/y    | integer | 0         | top-left corner of the rendered window                         |
// | crop_width/height  | integer | full film | size of the rendered window                                    |
// | temporal_bins      | integer | required  | number of time bins                                            |
// | start_opl          | float   | 0         | OPL at the start of bin 0 (scene units)                        |
// | bin_width_opl      | float   | required* | OPL covered by one bin (scene units)                           |
// | start_time         | float   | 0         | the same in seconds (scene units = metres; OPL = c t)          |
// | bin_width_time     | float   | required* | (*) give bin_width_opl or bin_width_time, not both forms       |
// | time_filter        | string  | "box"     | temporal reconstruction: box (no spread), tent, gaussian       |
// | time_filter_width  | float   | 1 / 0.5   | tent half-width / gaussian standard deviation, in bins         |
// | complete_steady    | boolean | false     | trace light past the window: complete steady image and `after` |
// | write_volume       | boolean | true      | keep <stem>.npy (float32, shape (height, width, bins, 3))      |
// | write_frames       | boolean | false     | write <stem>_frames/frame_NNNNN.exr, one per bin               |
// | (nested rfilter)   | rfilter | box       | pixel filter (any; wider than a pixel, tiles carry a border merged as they stream) |
//
// Always written: <stem>.exr + <stem>.png (the steady image: all light that
// arrives before the horizon, i.e. the window's end plus the time filter's
// reach; with complete_steady all light), <stem>_before.exr and <stem>_after.exr.
#include <femto/core/plugin.h>
#include <femto/film/transient_film.h>

FEMTO_EXPORT_PLUGIN(femto::TransientFilm, Film, "transient", "time-resolved film: .npy volume, EXR frames, steady EXR")
