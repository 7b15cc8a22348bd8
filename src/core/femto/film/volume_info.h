#pragma once
// What a transient .npy volume does not say by itself: its time window and
// where its pixels lie on the film. A transient film writes it beside the
// volume as a small JSON sidecar, <stem>.json (see docs/transient-film.md):
//
//   {"format": "femto transient volume", "version": 1,
//    "width": 64, "height": 64, "bins": 512,
//    "time_unit": "opl", "start_opl": 3, "bin_width_opl": 0.02, "end_opl": 13.24,
//    "film_width": 64, "film_height": 64, "crop": [0, 0, 64, 64],
//    "time_filter": "box",
//    "passes": 12, "spp_per_pass": 4, "spp": 48, "seed": 0,
//    "time_limit_seconds": 30, "time_clock": "wall", "time_limit_reached": true}
//
// The last two lines say how the volume was rendered (absent from older
// sidecars): the passes reached, so that `femto render --passes 12 --spp 4
// --seed 0` renders the same bits without a time limit. No times: the files
// of a render depend on its seed and passes only (MPI ranks, threads).
//
// Tools that read volumes (femto compare, the viewers) use it to refuse
// volumes of different windows and to label time axes; a volume without one
// (older renders, volumes made elsewhere) is still readable by shape alone.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <utility>
#include <vector>
#include <string>

#include <femto/math/vector.h>
#include <femto/time/time_grid.h>

namespace femto {

/// How a volume was rendered (the render's pass count and budget).
struct RenderRecord {
  int passes = 0, samplesPerPass = 0;
  uint64_t seed = 0;
  double timeLimit = 0.0;  // seconds; 0: none
  std::string timeClock;   // "wall" / "cpu" (with a time limit)
  bool timeLimitReached = false;
};

struct VolumeInfo {
  int width = 0, height = 0;  // of the volume (the film's crop window)
  TimeGrid grid;              // start and bin width in optical path length (scene units)
  Point2i filmSize{0, 0}, cropOffset{0, 0};
  std::string timeFilter = "box";
  std::optional<RenderRecord> render;  // absent from sidecars written before it
  /// More fields, written after the others as given: (key, JSON value)
  /// (an NLOS capture's geometry: renderTransient). Not read back.
  std::vector<std::pair<std::string, std::string>> extra;
};

/// The sidecar of `volume`: the same path with extension .json.
std::filesystem::path volumeInfoPath(const std::filesystem::path& volume);
/// Write `info` as JSON to `path` (atomically).
void writeVolumeInfo(const std::filesystem::path& path, const VolumeInfo& info);
/// The sidecar of the volume `volume`, or nothing if there is none; a sidecar
/// that exists but is malformed is an error naming it.
std::optional<VolumeInfo> readVolumeInfo(const std::filesystem::path& volume);

/// Whether two windows are the same up to float rounding (films store their
/// parameters as float, so windows given in seconds or OPL round the same way).
bool sameTimeWindow(const TimeGrid& a, const TimeGrid& b);
/// "512 bins of OPL 0.02 from 3 to 13.24" (for messages).
std::string describeTimeWindow(const TimeGrid& grid);

}  // namespace femto
