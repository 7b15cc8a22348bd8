#include <femto/analysis/compare_files.h>

#include <algorithm>
#include <charconv>

#include <femto/base/error.h>
#include <femto/core/log.h>
#include <femto/image/image_io.h>
#include <femto/film/npy_volume.h>
#include <femto/film/volume_info.h>

namespace femto {
namespace {

namespace fs = std::filesystem;

/// Bytes of one file's pixels read at a time (two files are read at once).
constexpr size_t ChunkBytes = size_t(8) << 20;

std::string ref(const Comparison& c) { return str("REF \"", c.reference.string(), "\""); }
std::string tst(const Comparison& c) { return str("TEST \"", c.test.string(), "\""); }

bool isVolume(const fs::path& path) { return path.extension() == ".npy"; }

std::optional<Bitmap> readMask(const CompareSettings& settings) {
  if (settings.mask.empty()) return std::nullopt;
  return readImage(settings.mask);
}

/// An image's colour channels: alpha (a 4th channel) is coverage, not an error.
int colourChannels(const Bitmap& image) { return image.channels == 4 ? 3 : image.channels; }

void compareImages(Comparison& c, const CompareSettings& settings) {
  Bitmap r = readImage(c.reference), t = readImage(c.test);
  if (r.width != t.width || r.height != t.height)
    throw Error(str(ref(c), " is ", r.width, "x", r.height, ", ", tst(c), " is ", t.width, "x", t.height));
  if (colourChannels(r) != colourChannels(t))
    throw Error(str(ref(c), " has ", r.channels, " channels, ", tst(c), " has ", t.channels));
  c.width = r.width, c.height = r.height, c.channels = colourChannels(r);
  std::optional<Bitmap> mask = readMask(settings);
  PixelRegion region(c.width, c.height, settings.crop, mask ? &*mask : nullptr, settings.mask.string());
  c.pixels = region.pixelCount();
  ErrorAccumulator acc(c.epsilon);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x)
      if (region.contains(x, y)) acc.add(r.pixel(x, y), t.pixel(x, y), size_t(c.channels));
  c.metrics = acc.metrics();
}

/// The volumes' time window from their sidecars: both must agree; a missing
/// sidecar leaves only the shape to compare (with a warning).
void checkTimeWindows(Comparison& c) {
  std::optional<VolumeInfo> r = readVolumeInfo(c.reference), t = readVolumeInfo(c.test);
  if (!r || !t) {
    logWarn("no time-window sidecar (", volumeInfoPath(!r ? c.reference : c.test).string(),
            "): the volumes are compared by shape only");
    return;
  }
  if (!sameTimeWindow(r->grid, t->grid))
    throw Error(str(ref(c), " covers ", describeTimeWindow(r->grid), ", ", tst(c), " covers ",
                    describeTimeWindow(t->grid)));
  if (r->cropOffset != t->cropOffset || r->filmSize != t->filmSize)
    throw Error(str(ref(c), " is the crop at ", r->cropOffset.x, ",", r->cropOffset.y, " of a ", r->filmSize.x, "x",
                    r->filmSize.y, " film, ", tst(c), " the crop at ", t->cropOffset.x, ",", t->cropOffset.y, " of a ",
                    t->filmSize.x, "x", t->filmSize.y, " film"));
  c.grid = r->grid;
}

void resolveBinWindow(Comparison& c, const CompareSettings& settings) {
  c.binBegin = settings.bins.begin.value_or(0);
  c.binEnd = settings.bins.end.value_or(c.bins);
  if (c.binBegin < 0 || c.binEnd > c.bins || c.binBegin >= c.binEnd)
    throw Error(str("--bins ", c.binBegin, ":", c.binEnd, " is not a non-empty range inside the ", c.bins,
                    " time bins of the volumes (0:", c.bins, ")"));
}

void compareVolumes(Comparison& c, const CompareSettings& settings) {
  NpyVolume r = NpyVolume::open(c.reference), t = NpyVolume::open(c.test);
  if (r.width() != t.width() || r.height() != t.height())
    throw Error(str(ref(c), " is ", r.width(), "x", r.height(), ", ", tst(c), " is ", t.width(), "x", t.height()));
  if (r.bins() != t.bins())
    throw Error(str(ref(c), " has ", r.bins(), " time bins, ", tst(c), " has ", t.bins()));
  c.transient = true;
  c.width = r.width(), c.height = r.height(), c.channels = 3, c.bins = r.bins();
  checkTimeWindows(c);
  resolveBinWindow(c, settings);
  std::optional<Bitmap> mask = readMask(settings);
  PixelRegion region(c.width, c.height, settings.crop, mask ? &*mask : nullptr, settings.mask.string());
  c.pixels = region.pixelCount();

  // Stream runs of pixels of one row (each pixel's bins are contiguous), at
  // most ChunkBytes per file at a time, so any volume size needs bounded memory.
  const size_t pixelFloats = size_t(c.bins) * 3;
  const int chunk = int(std::clamp<size_t>(ChunkBytes / (pixelFloats * sizeof(float)), 1, size_t(c.width)));
  std::vector<float> rb(size_t(chunk) * pixelFloats), tb(rb.size());
  std::vector<ErrorAccumulator> perBin(size_t(c.binEnd - c.binBegin), ErrorAccumulator(c.epsilon));
  ErrorAccumulator integral(c.epsilon);
  const PixelRect& box = region.bounds();
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x0 = box.x; x0 < box.x + box.width; x0 += chunk) {
      const int count = std::min(chunk, box.x + box.width - x0);
      r.readPixels(y, x0, count, rb.data());
      t.readPixels(y, x0, count, tb.data());
      for (int i = 0; i < count; ++i) {
        if (!region.contains(x0 + i, y)) continue;
        const float* rp = &rb[size_t(i) * pixelFloats];
        const float* tp = &tb[size_t(i) * pixelFloats];
        double rSum[3] = {0, 0, 0}, tSum[3] = {0, 0, 0};
        for (int b = c.binBegin; b < c.binEnd; ++b) {
          const size_t o = size_t(b) * 3;
          perBin[size_t(b - c.binBegin)].add(rp + o, tp + o, 3);
          for (int k = 0; k < 3; ++k) rSum[k] += rp[o + k], tSum[k] += tp[o + k];
        }
        for (int k = 0; k < 3; ++k) integral.add(rSum[k], tSum[k]);
      }
    }
  ErrorAccumulator all(c.epsilon);
  c.perBin.reserve(perBin.size());
  for (const ErrorAccumulator& acc : perBin) {
    all.merge(acc);
    c.perBin.push_back(acc.metrics());
  }
  c.metrics = all.metrics();
  c.integral = integral.metrics();
}

std::optional<int> parseBin(std::string_view text, const std::string& option, const std::string& whole) {
  if (text.empty()) return std::nullopt;
  int v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < 0)
    throw Error(str(option, " expects FIRST:END with bin numbers >= 0 (end exclusive, either may be left out), got \"",
                    whole, "\""));
  return v;
}

}  // namespace

BinRange parseBinRange(const std::string& text, const std::string& option) {
  size_t colon = text.find(':');
  if (colon == std::string::npos)
    throw Error(str(option, " expects FIRST:END with bin numbers >= 0 (end exclusive, either may be left out), got \"",
                    text, "\""));
  std::string_view view(text);
  return {parseBin(view.substr(0, colon), option, text), parseBin(view.substr(colon + 1), option, text)};
}

Comparison compareFiles(const fs::path& reference, const fs::path& test, const CompareSettings& settings) {
  Comparison c;
  c.reference = reference, c.test = test, c.epsilon = settings.epsilon;
  if (!(settings.epsilon > 0.0)) throw Error(str("--epsilon must be positive, got ", settings.epsilon));
  for (const fs::path& p : {reference, test})
    if (!fs::exists(p)) throw Error(str("\"", p.string(), "\" does not exist"));
  bool rv = isVolume(reference), tv = isVolume(test);
  if (rv != tv)
    throw Error(str(ref(c), " is ", rv ? "a transient volume (.npy)" : "an image", ", ", tst(c), " is ",
                    tv ? "a transient volume (.npy)" : "an image"));
  if (rv) {
    compareVolumes(c, settings);
  } else {
    if (settings.binsGiven)
      throw Error(str("--bins applies to transient volumes (.npy); ", ref(c), " and ", tst(c), " are images"));
    compareImages(c, settings);
  }
  return c;
}

}  // namespace femto
