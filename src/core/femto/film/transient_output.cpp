#include <femto/film/transient_output.h>

#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <system_error>
#include <vector>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/core/resources.h>
#include <femto/film/volume_info.h>
#include <femto/film/volume_scan.h>

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
  if (path.empty()) return;
  paths_ = film.outputPaths(path);
  if (!film.writesVolume() && !film.writesFrames()) return;
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

TransientOutput::~TransientOutput() {
  if (!volumeTmp_.empty()) {  // not finished (an exception): leave no temporary behind
    volume_.reset();
    std::error_code ec;
    std::filesystem::remove(volumeTmp_, ec);
  }
}

void TransientOutput::consume(TransientTile& tile, int pass) {
  tile.normalize();
  const Point2i origin = tile.offset() - film_.cropOffset();
  // Running mean over passes: pass 0 stores the tile as it is.
  const float keep = float(pass) / float(pass + 1), add = 1.0f / float(pass + 1);
  auto fold = [&](float* stored, const float* fresh, size_t count) {
    for (size_t k = 0; k < count; ++k) stored[k] = pass == 0 ? fresh[k] : keep * stored[k] + add * fresh[k];
  };
  std::vector<float> row;
  const size_t rowFloats = size_t(tile.size().x) * size_t(tile.bins()) * 3;
  for (int y = 0; y < tile.size().y; ++y) {
    if (volume_) {
      if (pass == 0) {
        volume_->writePixels(origin.y + y, origin.x, tile.size().x, tile.row(y));
      } else {
        row.resize(rowFloats);
        volume_->readPixels(origin.y + y, origin.x, tile.size().x, row.data());
        fold(row.data(), tile.row(y), rowFloats);
        volume_->writePixels(origin.y + y, origin.x, tile.size().x, row.data());
      }
    }
    for (int x = 0; x < tile.size().x; ++x) {
      fold(steady_.pixel(origin.x + x, origin.y + y), tile.steady(x, y), 3);
      fold(before_.pixel(origin.x + x, origin.y + y), tile.before(x, y), 3);
      fold(after_.pixel(origin.x + x, origin.y + y), tile.after(x, y), 3);
    }
  }
}

VolumeInfo TransientOutput::volumeInfo(const RenderRecord* record) const {
  VolumeInfo info;
  info.width = film_.cropSize().x, info.height = film_.cropSize().y;
  info.grid = film_.timeGrid();
  info.filmSize = film_.size(), info.cropOffset = film_.cropOffset();
  info.timeFilter = film_.timeFilter().name();
  if (record) info.render = *record;
  return info;
}

void TransientOutput::finish(const std::function<void(int done, int total)>& onFrames, const RenderRecord* record) {
  if (!paths_) return;
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
