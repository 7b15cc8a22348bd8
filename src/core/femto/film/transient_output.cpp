#include <femto/film/transient_output.h>

#include <femto/render/image_block.h>
#include <femto/render/rfilter.h>

#include <tbb/parallel_for.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/core/log.h>
#include <femto/core/resources.h>
#include <femto/film/volume_info.h>
#include <femto/film/volume_scan.h>
#include <femto/loop/tile_distribution.h>

namespace femto {
namespace {

/// Memory for the frames being assembled (one batch).
constexpr size_t FrameBudgetBytes = size_t(32) << 20;

}  // namespace

std::string frameFileName(int bin, int bins, const std::string& extension) {
  int digits = std::max(5, int(std::to_string(std::max(bins - 1, 0)).size()));
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%0*d", digits, bin);
  return name + extension;
}

void removeStaleFrames(const std::filesystem::path& dir, const std::string& extension) {
  std::error_code ec;
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && entry.path().extension() == extension) stale.push_back(entry.path());
  }
  for (const auto& p : stale) std::filesystem::remove(p, ec);
}

void writeFrames(const NpyVolume& volume, const std::filesystem::path& dir, size_t budgetBytes,
                 const std::function<void(int done, int total)>& onBatch) {
  const int bins = volume.bins();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(str("cannot create \"", dir.string(), "\": ", ec.message()));
  removeStaleFrames(dir, ".exr");
  // A batch of frames fills the budget; each pass reads only the batch's bins
  // of every pixel (one contiguous run per pixel), so the volume is read once
  // in total whatever the number of passes.
  const int batch = framesPerBatch(volume, budgetBytes);
  for (int b0 = 0; b0 < bins; b0 += batch) {
    const int count = std::min(batch, bins - b0);
    std::vector<Bitmap> frames = readFrames(volume, b0, count);
    // Frames are independent files: compress and write them in parallel.
    auto writeFrame = [&](int k) { writeEXR(dir / frameFileName(b0 + k, bins, ".exr"), frames[size_t(k)]); };
    ForkJoinEdges edges;
    tbb::parallel_for(0, count, edges.task(writeFrame));
    edges.join();
    if (onBatch) onBatch(b0 + count, bins);
  }
}

TransientOutput::TransientOutput(const TransientFilm& film, const std::filesystem::path& path) : film_(film) {
  const Point2i crop = film.cropSize();
  const double pixels = double(crop.x) * double(crop.y);
  requireMemory(3.0 * pixels * 3.0 * sizeof(float) + FrameBudgetBytes,
                str("the steady, before and after images of ", crop.x, "x", crop.y, " pixels"),
                "render a smaller image (--resolution WxH) or a crop window");
  steady_ = before_ = after_ = Bitmap(crop.x, crop.y, 3);
  // A filter wider than a pixel holds a band of tile rows until their
  // neighbours come (consumeBordered): up to 2 x reach + 2 rows of at most
  // 32-pixel tiles, with their borders.
  const ReconstructionFilter* filter = film.filter();
  const bool bordered = filter && filter->radius() > 0.5f;
  if (bordered) {
    const int border = filterBorder(filter);
    const double rows = 4.0 * 32.0 + 4.0 * border, width = crop.x + 2.0 * border;
    requireMemory(rows * width * (3.0 * film.timeGrid().bins + 10.0) * sizeof(float),
                  str("the band of tiles a ", filter->radius(), "-pixel filter holds (", crop.x, " pixels wide x ",
                      film.timeGrid().bins, " bins)"),
                  "use <rfilter type=\"box\"/>, fewer time bins or a narrower image");
  }
  if (!path.empty()) {
    paths_ = film.outputPaths(path);
    if (film.writesVolume() || film.writesFrames()) createVolume();
  }
  TileDistribution* distribution = tileDistribution();
  const bool distributed = distribution && distribution->ranks() > 1;
  if (distributed && !bordered) shareVolume(*distribution);
  storesAlone_ = !bordered && (!distributed || shared_);
}

void TransientOutput::createVolume() {
  const TransientFilm& film = film_;
  const Point2i crop = film.cropSize();
  const double pixels = double(crop.x) * double(crop.y);
  const int bins = film.timeGrid().bins;
  requireDisk(paths_->volume, pixels * double(bins) * 3.0 * sizeof(float),
              str("the transient volume of ", crop.x, "x", crop.y, " pixels x ", bins, " bins"),
              "use fewer time bins or pixels, or write elsewhere (-o)");
  // Written under a temporary name and renamed at the end, as every output:
  // a reader never sees a half-written volume under the final name.
  std::filesystem::path dir = paths_->volume.has_parent_path() ? paths_->volume.parent_path() : ".";
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  volumeTmp_ = dir / (".tmp-" + std::to_string(::getpid()) + "-" + paths_->volume.filename().string());
  volumeTmpGuard_.emplace(volumeTmp_);
  volume_.emplace(NpyVolume::create(volumeTmp_, crop.y, crop.x, film.timeGrid().bins));
}

namespace {

/// Is `folder` on a network file system whose clients cache pages without
/// seeing each other's writes at once (NFS, SMB)? Ranks on several nodes
/// cannot then read back the rows another rank wrote the pass before.
bool cachesWithoutCoherence(const std::filesystem::path& folder) {
  struct statfs info {};
  if (::statfs(folder.c_str(), &info) != 0) return false;
  constexpr long NfsMagic = 0x6969, SmbMagic = 0x517B, Smb2Magic = 0xFE534D42, CifsMagic = 0xFF534D42;
  const long type = long(info.f_type);
  return type == NfsMagic || type == SmbMagic || type == Smb2Magic || type == CifsMagic;
}

}  // namespace

void TransientOutput::shareVolume(TileDistribution& distribution) {
  // Rank 0 (the one given a path) decides and names its temporary volume:
  // "+path" (or "+" with no volume) and every rank stores the tiles it
  // renders, the others opening the volume to write their rows; "-" and rank
  // 0 stores every tile. The volume stays rank 0's to rename or remove.
  std::vector<char> mine;
  if (paths_) mine.push_back(volume_ && cachesWithoutCoherence(volumeTmp_.parent_path()) ? '-' : '+');
  if (volume_ && mine[0] == '+') {
    const std::string path = volumeTmp_.string();
    mine.insert(mine.end(), path.begin(), path.end());
  }
  const std::vector<char> all = distribution.gatherAll(mine);
  if (!all.empty() && all[0] == '-') {
    logInfo("the output folder is on a network file system (NFS or SMB): rank 0 writes every tile of the volume");
    return;
  }
  shared_ = &distribution;
  if (!volume_ && all.size() > 1)
    volume_.emplace(NpyVolume::open(std::filesystem::path(std::string(all.begin() + 1, all.end())), /*writable=*/true));
}

void TransientOutput::shareStoredPixels() {
  // Per rectangle: origin and size (4 ints), then its steady, before and
  // after RGB, row by row. Every rank ends the pass with every pixel's value,
  // the one its storing rank folded, whichever rank stores it next pass.
  std::vector<char> mine;
  auto put = [&](const void* data, size_t bytes) {
    const char* p = static_cast<const char*>(data);
    mine.insert(mine.end(), p, p + bytes);
  };
  for (const auto& [origin, size] : storedRects_) {
    const int rect[4] = {origin.x, origin.y, size.x, size.y};
    put(rect, sizeof rect);
    for (const Bitmap* image : {&steady_, &before_, &after_})
      for (int y = 0; y < size.y; ++y) put(image->pixel(origin.x, origin.y + y), size_t(size.x) * 3 * sizeof(float));
  }
  storedRects_.clear();
  const auto start = std::chrono::steady_clock::now();
  const std::vector<char> all = shared_->gatherAll(mine);
  for (size_t at = 0; at < all.size();) {
    int rect[4];
    std::memcpy(rect, &all[at], sizeof rect);
    at += sizeof rect;
    const size_t rowBytes = size_t(rect[2]) * 3 * sizeof(float);
    for (Bitmap* image : {&steady_, &before_, &after_})
      for (int y = 0; y < rect[3]; ++y, at += rowBytes) std::memcpy(image->pixel(rect[0], rect[1] + y), &all[at], rowBytes);
  }
  logDebug("the ranks exchanged the pass's stored image pixels (", all.size(), " bytes) in ",
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), " s");
}

TransientOutput::~TransientOutput() {
  if (!volumeTmp_.empty()) {  // not finished (an exception): leave no temporary behind
    volume_.reset();
    std::error_code ec;
    std::filesystem::remove(volumeTmp_, ec);
  }
}

template <typename RowFn, typename RgbFn>
void TransientOutput::store(const Point2i& origin, const Point2i& size, int bins, int pass, RowFn&& rowOf,
                            RgbFn&& rgb) {
  // Running mean over passes: pass 0 stores the pixels as they are.
  const float keep = float(pass) / float(pass + 1), add = 1.0f / float(pass + 1);
  auto fold = [&](float* stored, const float* fresh, size_t count) {
    for (size_t k = 0; k < count; ++k) stored[k] = pass == 0 ? fresh[k] : keep * stored[k] + add * fresh[k];
  };
  std::vector<float> row;
  const size_t rowFloats = size_t(size.x) * size_t(bins) * 3;
  for (int y = 0; y < size.y; ++y) {
    if (volume_) {
      if (pass == 0) {
        volume_->writePixels(origin.y + y, origin.x, size.x, rowOf(y));
      } else {
        row.resize(rowFloats);
        volume_->readPixels(origin.y + y, origin.x, size.x, row.data());
        fold(row.data(), rowOf(y), rowFloats);
        volume_->writePixels(origin.y + y, origin.x, size.x, row.data());
      }
    }
    for (int x = 0; x < size.x; ++x) {
      fold(steady_.pixel(origin.x + x, origin.y + y), rgb(0, x, y), 3);
      fold(before_.pixel(origin.x + x, origin.y + y), rgb(1, x, y), 3);
      fold(after_.pixel(origin.x + x, origin.y + y), rgb(2, x, y), 3);
    }
  }
}

void TransientOutput::consume(TransientTile& tile, int pass) {
  if (tile.border() > 0) return consumeBordered(tile, pass);
  tile.normalize();
  if (shared_) {
    std::lock_guard lock(storedMutex_);  // tiles stored alone are stored in parallel
    storedRects_.emplace_back(tile.offset() - film_.cropOffset(), tile.size());
  }
  store(tile.offset() - film_.cropOffset(), tile.size(), tile.bins(), pass, [&](int y) { return tile.row(y); },
        [&](int k, int x, int y) { return k == 0 ? tile.steady(x, y) : k == 1 ? tile.before(x, y) : tile.after(x, y); });
}

void TransientOutput::consumeBordered(TransientTile& tile, int pass) {
  const Point2i local = tile.offset() - film_.cropOffset();
  if (heldPass_ != pass) {
    // The pass's first tile is the top-left one, of the full tile size (or the whole crop window).
    if (local != Point2i(0, 0)) throw Error("a bordered transient tile came before the pass's first tile");
    endPass(heldPass_);
    heldPass_ = pass;
    tileSide_ = tile.size();
    const Point2i crop = film_.cropSize();
    tileCount_ = Point2i((crop.x + tileSide_.x - 1) / tileSide_.x, (crop.y + tileSide_.y - 1) / tileSide_.y);
    tileReach_ = (tile.border() + std::min(tileSide_.x, tileSide_.y) - 1) / std::min(tileSide_.x, tileSide_.y);
    held_.assign(size_t(tileCount_.x) * size_t(tileCount_.y), Held{});
  }
  const int tx = local.x / tileSide_.x, ty = local.y / tileSide_.y;
  const int k = ty * tileCount_.x + tx;
  held_[k].raw = tile.takeRaw();
  held_[k].present = true;
  // Tiles come in row-major order: those whose every neighbour has come can be stored.
  for (int y = std::max(0, ty - tileReach_); y <= ty; ++y)
    for (int x = std::max(0, tx - tileReach_); x <= std::min(tileCount_.x - 1, tx + tileReach_); ++x) {
      const int j = y * tileCount_.x + x;
      if (!held_[j].present || held_[j].stored) continue;
      bool ready = true;
      for (int ny = y - tileReach_; ny <= y + tileReach_ && ready; ++ny)
        for (int nx = x - tileReach_; nx <= x + tileReach_ && ready; ++nx)
          if (ny >= 0 && nx >= 0 && ny < tileCount_.y && nx < tileCount_.x) ready = held_[ny * tileCount_.x + nx].present;
      if (ready) finalizeTile(j, pass);
    }
  releaseTiles(ty);
}

void TransientOutput::finalizeTile(int k, int pass) {
  const TransientTile::Raw& self = held_[k].raw;
  const int bins = film_.timeGrid().bins;
  const int tx = k % tileCount_.x, ty = k / tileCount_.x;
  std::vector<float> volume(size_t(self.size.x) * size_t(self.size.y) * size_t(bins) * 3, 0.0f);
  std::vector<float> rgb(size_t(self.size.x) * size_t(self.size.y) * 9, 0.0f), weight(size_t(self.size.x) * self.size.y, 0.0f);
  // Every held tile within reach, in tile order: each pixel's sums in one fixed order.
  for (int ny = ty - tileReach_; ny <= ty + tileReach_; ++ny)
    for (int nx = tx - tileReach_; nx <= tx + tileReach_; ++nx) {
      if (ny < 0 || nx < 0 || ny >= tileCount_.y || nx >= tileCount_.x) continue;
      const Held& h = held_[ny * tileCount_.x + nx];
      if (!h.present) continue;
      const TransientTile::Raw& u = h.raw;
      const int storedW = u.size.x + 2 * u.border, storedH = u.size.y + 2 * u.border;
      for (int y = 0; y < self.size.y; ++y)
        for (int x = 0; x < self.size.x; ++x) {
          // The pixel in u's stored area.
          const int ux = self.offset.x + x - u.offset.x + u.border, uy = self.offset.y + y - u.offset.y + u.border;
          if (ux < 0 || uy < 0 || ux >= storedW || uy >= storedH) continue;
          const size_t i = size_t(uy) * size_t(storedW) + size_t(ux), o = size_t(y) * size_t(self.size.x) + size_t(x);
          weight[o] += u.weight[i];
          const float* src = &u.volume[i * size_t(bins) * 3];
          float* dst = &volume[o * size_t(bins) * 3];
          for (size_t c = 0; c < size_t(bins) * 3; ++c) dst[c] += src[c];
          for (int c = 0; c < 3; ++c) {
            rgb[o * 9 + c] += u.steady[i * 3 + c];
            rgb[o * 9 + 3 + c] += u.before[i * 3 + c];
            rgb[o * 9 + 6 + c] += u.after[i * 3 + c];
          }
        }
    }
  // The filter's weighted mean (Mitsuba's: sum / weight, 0 where nothing landed).
  for (size_t o = 0; o < weight.size(); ++o) {
    const float scale = weight[o] != 0.0f ? 1.0f / weight[o] : 0.0f;
    for (size_t c = 0; c < size_t(bins) * 3; ++c) volume[o * size_t(bins) * 3 + c] *= scale;
    for (int c = 0; c < 9; ++c) rgb[o * 9 + c] *= scale;
  }
  const size_t rowFloats = size_t(self.size.x) * size_t(bins) * 3;
  store(self.offset - film_.cropOffset(), self.size, bins, pass, [&](int y) { return &volume[size_t(y) * rowFloats]; },
        [&](int c, int x, int y) { return &rgb[(size_t(y) * size_t(self.size.x) + size_t(x)) * 9 + size_t(c) * 3]; });
  held_[k].stored = true;
}

void TransientOutput::releaseTiles(int row) {
  // A tile's sums are needed until every tile its border reaches is stored:
  // only tiles of the rows just above `row` can have become free.
  const int first = std::max(0, row - 2 * tileReach_ - 1) * tileCount_.x;
  const int last = std::min(int(held_.size()), (row + 1) * tileCount_.x);
  for (int k = first; k < last; ++k) {
    Held& h = held_[k];
    if (!h.present || h.raw.volume.empty()) continue;
    const int tx = k % tileCount_.x, ty = k / tileCount_.x;
    bool needed = false;
    for (int ny = ty - tileReach_; ny <= ty + tileReach_ && !needed; ++ny)
      for (int nx = tx - tileReach_; nx <= tx + tileReach_ && !needed; ++nx)
        if (ny >= 0 && nx >= 0 && ny < tileCount_.y && nx < tileCount_.x) needed = !held_[ny * tileCount_.x + nx].stored;
    if (!needed) h.raw = TransientTile::Raw{};
  }
}

void TransientOutput::endPass(int pass) {
  if (shared_) return shareStoredPixels();  // no bordered tiles where ranks store their own
  if (pass < 0 || pass != heldPass_) return;
  for (int k = 0; k < int(held_.size()); ++k)
    if (held_[k].present && !held_[k].stored) finalizeTile(k, pass);
  held_.clear();
  heldPass_ = -1;
}

VolumeInfo TransientOutput::volumeInfo(const RenderRecord* record) const {
  VolumeInfo info;
  info.width = film_.cropSize().x, info.height = film_.cropSize().y;
  info.grid = film_.timeGrid();
  info.filmSize = film_.size(), info.cropOffset = film_.cropOffset();
  info.timeFilter = film_.timeFilter().name();
  if (record) info.render = *record;
  info.extra = extra_;
  return info;
}

void TransientOutput::finish(const std::function<void(int done, int total)>& onFrames, const RenderRecord* record) {
  if (!paths_) {
    volume_.reset();  // a rank that wrote its tiles into rank 0's volume
    return;
  }
  Film::writeExrWithPreview(paths_->steady, steady_);
  writeEXR(paths_->before, before_);
  writeEXR(paths_->after, after_);
  if (!volume_) return;
  if (film_.writesFrames()) writeFrames(*volume_, paths_->framesDir, FrameBudgetBytes, onFrames);
  volume_.reset();
  std::error_code ec;
  if (film_.writesVolume()) {
    std::filesystem::rename(volumeTmp_, paths_->volume, ec);
    if (!ec) volumeTmpGuard_.reset();
    if (ec) throw Error(str("cannot write \"", paths_->volume.string(), "\": ", ec.message()));
    writeVolumeInfo(volumeInfoPath(paths_->volume), volumeInfo(record));
  } else {
    std::filesystem::remove(volumeTmp_, ec);
  }
  volumeTmpGuard_.reset();
  volumeTmp_.clear();
}

}  // namespace femto
