#pragma once
// The files of one transient render, written as the render goes: finished
// tiles go straight into the .npy volume at their offsets (in parallel, or
// in tile order when a filter's borders must be summed) and are then freed; the steady, before and after images (one RGB value per
// pixel, small) are kept and written at the end, followed by one EXR frame per
// time bin read back from the volume a batch of frames at a time. Memory stays
// bounded by the tiles in flight plus a fixed frame budget, whatever the
// number of bins.
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <femto/base/temp_files.h>
#include <femto/image/image_io.h>
#include <femto/film/npy_volume.h>
#include <femto/film/transient_film.h>
#include <femto/film/transient_tile.h>
#include <femto/film/volume_info.h>

namespace femto {

class TileDistribution;

class TransientOutput {
 public:
  /// `path` as given to the render (see TransientFilm::outputPaths); empty:
  /// nothing is written, the images are only kept in memory.
  TransientOutput(const TransientFilm& film, const std::filesystem::path& path);
  ~TransientOutput();

  /// Normalise a finished tile and store it (volume rows to disk, steady,
  /// before and after into the images). Pass `pass` > 0 of a progressive
  /// render folds the tile into what earlier passes stored as a running mean,
  /// old + (new - old) / (pass + 1), reading the volume rows back.
  /// Tiles of a filter wider than a pixel (TransientTile::border()) are held
  /// until every tile their borders reach has come; each pixel is then the
  /// sum of every tile's share in tile order over their filter weights
  /// (the same bits for any thread or rank count), and a tile is freed once
  /// its neighbours are stored: memory holds a band of a few tile rows.
  void consume(TransientTile& tile, int pass = 0);
  /// The end of pass `pass`: bordered tiles still held are stored with the
  /// neighbours that came (all of them, unless the pass was cancelled).
  /// Where ranks store their own tiles, every rank calls it: the ranks then
  /// exchange the image pixels they stored (a collective).
  void endPass(int pass);
  /// Is each tile stored alone, so consume() may run in parallel on the
  /// threads that render the tiles (renderTileStream's consumeWhereRendered)?
  /// So without a filter border. When processes share the render's tiles
  /// (tile_distribution.h) each then stores the tiles it renders, writing
  /// their rows into the one volume rank 0 created (positioned writes, which
  /// every node must see coherently: not when the output folder is on NFS
  /// or SMB, where rank 0 stores every tile).
  bool storesTilesAlone() const { return storesAlone_; }
  /// Write the steady EXR + PNG, before/after EXRs and the frames, and put the
  /// volume in place. Call once, after the last tile (also after a cancel).
  /// `onFrames(done, total)` is called after each batch of frames written.
  /// `record`, when given, goes into the volume's sidecar (how it was rendered).
  void finish(const std::function<void(int done, int total)>& onFrames = {}, const RenderRecord* record = nullptr);
  /// Fields finish() adds to the volume's sidecar (VolumeInfo::extra).
  void setSidecarExtra(std::vector<std::pair<std::string, std::string>> extra) { extra_ = std::move(extra); }
  /// The volume's path (empty when nothing is written).
  std::filesystem::path volumePath() const { return paths_ ? paths_->volume : std::filesystem::path(); }
  /// Does finish() write one frame per bin (the longest part of it)?
  bool writesFrames() const { return paths_ && volume_ && film_.writesFrames(); }

  /// Developed crop-window images (valid for consumed tiles).
  const Bitmap& steady() const { return steady_; }
  const Bitmap& before() const { return before_; }
  const Bitmap& after() const { return after_; }

 private:
  /// The volume's sidecar (<stem>.json: time window, crop; volume_info.h).
  VolumeInfo volumeInfo(const RenderRecord* record) const;
  /// Store developed pixels of the crop-window rectangle at `origin` (rows of
  /// size.x pixels: `row(y)` bins x 3 floats each, `rgb(k, x, y)` the steady
  /// (k = 0), before (1) and after (2) RGB), folding pass `pass` into earlier ones.
  template <typename RowFn, typename RgbFn>
  void store(const Point2i& origin, const Point2i& size, int bins, int pass, RowFn&& row, RgbFn&& rgb);
  void consumeBordered(TransientTile& tile, int pass);
  /// The temporary volume, renamed into place by finish().
  void createVolume();
  /// Whether the ranks store their own tiles, and if so rank 0's temporary
  /// volume opened on every rank (a collective).
  void shareVolume(TileDistribution& distribution);
  /// Every rank's stored image pixels of this pass copied to every rank (a collective).
  void shareStoredPixels();
  /// Store held tile `k` (its neighbours' borders summed in) and free the tiles no longer needed.
  void finalizeTile(int k, int pass);
  void releaseTiles(int row);

  /// Bordered tiles of the current pass (tile grid of the crop window,
  /// row-major as the render loop hands tiles out).
  struct Held {
    TransientTile::Raw raw;
    bool present = false, stored = false;
  };
  std::vector<Held> held_;
  Point2i tileSide_{0, 0}, tileCount_{0, 0};
  int tileReach_ = 1;  // tiles a border reaches
  int heldPass_ = -1;

  bool storesAlone_ = false;
  TileDistribution* shared_ = nullptr;  // when ranks store their own tiles
  std::mutex storedMutex_;
  std::vector<std::pair<Point2i, Point2i>> storedRects_;  // (origin, size) stored here this pass

  const TransientFilm& film_;
  std::optional<TransientFilm::OutputPaths> paths_;
  std::filesystem::path volumeTmp_;
  std::optional<TempFileGuard> volumeTmpGuard_;  // removed even when a signal ends the process
  std::optional<NpyVolume> volume_;
  Bitmap steady_, before_, after_;
  std::vector<std::pair<std::string, std::string>> extra_;
};

/// Write one EXR per time bin of `volume` into `dir` (frame_00000.exr, ...;
/// stale frame_*.exr files there are removed first), reading the volume
/// again for each batch of frames that fits in `budgetBytes`.
/// `onBatch(done, total)`, when given, is called after each batch.
void writeFrames(const NpyVolume& volume, const std::filesystem::path& dir, size_t budgetBytes,
                 const std::function<void(int done, int total)>& onBatch = {});

/// "frame_00042" + extension: the file of `bin` among `bins` (at least five
/// digits, zero-padded, so names sort in time order).
std::string frameFileName(int bin, int bins, const std::string& extension);
/// Remove frame_*<extension> files from `dir` (left by an earlier, longer sequence).
void removeStaleFrames(const std::filesystem::path& dir, const std::string& extension);

}  // namespace femto
