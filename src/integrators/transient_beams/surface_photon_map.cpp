// SurfacePhotonMap: a hashed uniform grid over surface photons (see
// surface_photon_map.h).
#include <transient_beams/surface_photon_map.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <femto/base/error.h>
#include <femto/math/bbox.h>
#include <transient_beams/float_bounds.h>

namespace femto::beams {

double lastLegDelay(const SurfacePhoton& photon, const Point3f& x) {
  if (!(photon.legEta > 0.0f)) return 0.0;
  const double ox = double(x.x) - photon.p.x, oy = double(x.y) - photon.p.y, oz = double(x.z) - photon.p.z;
  const double along = ox * photon.wi.x + oy * photon.wi.y + oz * photon.wi.z;  // offset toward the leg's start
  if (!std::isfinite(photon.leg)) return -double(photon.legEta) * along;        // plane wave
  // |x - q| - leg with q = p + wi leg, without cancellation: (|x - q|^2 - leg^2) / (|x - q| + leg).
  const double leg = photon.leg, offset2 = ox * ox + oy * oy + oz * oz;
  const double toStart = std::sqrt(std::max(0.0, offset2 - 2.0 * leg * along + leg * leg));
  const double sum = toStart + leg;
  return sum > 0.0 ? double(photon.legEta) * (offset2 - 2.0 * leg * along) / sum : 0.0;
}

namespace {

// Cell coordinates are packed into 21 bits each.
constexpr int CoordBits = 21;
constexpr int MaxCells = (1 << CoordBits) - 1;

// splitmix64's finaliser (Steele et al. 2014): spreads neighbouring cell keys
// over the whole table.
uint64_t mixBits(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

uint64_t packCell(int x, int y, int z) {
  return uint64_t(x) | (uint64_t(y) << CoordBits) | (uint64_t(z) << (2 * CoordBits));
}

BoundingBox3f photonBounds(const std::vector<SurfacePhoton>& photons) {
  BoundingBox3f box;
  for (size_t i = 0; i < photons.size(); ++i) {
    if (!isFinite(photons[i].p))
      throw Error(str("SurfacePhotonMap: photon ", i, " has the non-finite position ", photons[i].p));
    box.expand(photons[i].p);
  }
  return box;
}

}  // namespace

SurfacePhotonMap::SurfacePhotonMap(std::vector<SurfacePhoton> photons) : photons_(std::move(photons)) {
  if (photons_.empty()) return;
  // Photons lie on surfaces: N photons on an area of about maxExtent^2 put
  // ~8 in a cell of side maxExtent * sqrt(8 / N).
  float extent = maxComponent(photonBounds(photons_).extents());
  build(extent * std::sqrt(8.0f / float(photons_.size())));
}

SurfacePhotonMap::SurfacePhotonMap(std::vector<SurfacePhoton> photons, float queryRadius)
    : photons_(std::move(photons)) {
  if (!std::isfinite(queryRadius) || !(queryRadius > 0.0f))
    throw Error(str("SurfacePhotonMap: the expected query radius must be finite and > 0, got ", queryRadius));
  build(queryRadius);
}

void SurfacePhotonMap::build(float cellSize) {
  cellSize_ = cellSize;
  if (photons_.empty()) return;
  if (photons_.size() >= (size_t(1) << 31))
    throw Error(str("SurfacePhotonMap: ", photons_.size(), " photons exceed the 2^31 a map can index"));
  BoundingBox3f box = photonBounds(photons_);
  gridMin_ = box.min;
  float extent = maxComponent(box.extents());
  // At most MaxCells cells along an axis (the packed key), and never a zero
  // cell (all photons at one point).
  cellSize_ = std::max({cellSize, extent / float(MaxCells - 1), 1e-30f});
  for (int k = 0; k < 3; ++k) gridRes_[k] = std::clamp(int(box.extents()[k] / cellSize_) + 1, 1, MaxCells);

  // Counting sort of the photons by bucket, stable (photon order within a
  // bucket), so the same photons always give the same map.
  size_t buckets = 1;
  while (buckets < 2 * photons_.size()) buckets <<= 1;
  std::vector<uint64_t> key(photons_.size());
  bucketStart_.assign(buckets + 1, 0);
  for (size_t i = 0; i < photons_.size(); ++i) {
    key[i] = cellKey(photons_[i].p);
    ++bucketStart_[(mixBits(key[i]) & (buckets - 1)) + 1];
  }
  for (size_t b = 0; b < buckets; ++b) bucketStart_[b + 1] += bucketStart_[b];
  std::vector<uint32_t> fill(bucketStart_.begin(), bucketStart_.end() - 1);
  order_.resize(photons_.size());
  sortedP_.resize(photons_.size());
  sortedKey_.resize(photons_.size());
  sortedOpl_.resize(photons_.size());
  for (size_t i = 0; i < photons_.size(); ++i) {
    uint32_t at = fill[mixBits(key[i]) & (buckets - 1)]++;
    order_[at] = uint32_t(i);
    sortedP_[at] = photons_[i].p;
    sortedKey_[at] = key[i];
    sortedOpl_[at] = floatAtLeast(photons_[i].opl);
    maxLegEta_ = std::max(maxLegEta_, photons_[i].legEta);
  }
}

uint64_t SurfacePhotonMap::cellKey(const Point3f& p) const {
  int c[3];
  for (int k = 0; k < 3; ++k) c[k] = std::clamp(int((p[k] - gridMin_[k]) / cellSize_), 0, gridRes_[k] - 1);
  return packCell(c[0], c[1], c[2]);
}

void SurfacePhotonMap::query(const Point3f& p, float radius, std::vector<uint32_t>& out, double minOpl) const {
  out.clear();
  if (photons_.empty() || !(radius >= 0.0f) || !isFinite(p)) return;
  // Time gating: a photon's light reaches p no later than opl + legEta radius.
  const float floor = floatAtMost(minOpl - double(maxLegEta_) * double(radius) * (1.0 + 1e-6));
  float r2 = radius * radius;
  // The cell range of the query box, widened by a hair so rounding in
  // p +- radius cannot drop a cell holding a photon at distance exactly
  // `radius`.
  float reach = radius * (1.0f + 1e-5f) + 1e-6f * maxComponent(abs(p)) + 1e-30f;
  int lo[3], hi[3];
  double cells = 1.0;
  for (int k = 0; k < 3; ++k) {
    float a = std::floor((p[k] - reach - gridMin_[k]) / cellSize_);
    float b = std::floor((p[k] + reach - gridMin_[k]) / cellSize_);
    if (b < 0.0f || a > float(gridRes_[k] - 1)) return;  // the sphere misses every photon
    lo[k] = a < 0.0f ? 0 : int(a);
    hi[k] = b > float(gridRes_[k] - 1) ? gridRes_[k] - 1 : int(b);
    cells *= double(hi[k] - lo[k] + 1);
  }
  // A radius far above the cell size: scanning every photon is cheaper.
  if (cells > double(photons_.size())) {
    for (size_t i = 0; i < sortedP_.size(); ++i)
      if (sortedOpl_[i] >= floor && squaredLength(sortedP_[i] - p) <= r2) out.push_back(order_[i]);
    return;
  }
  uint64_t mask = bucketStart_.size() - 2;
  for (int z = lo[2]; z <= hi[2]; ++z)
    for (int y = lo[1]; y <= hi[1]; ++y)
      for (int x = lo[0]; x <= hi[0]; ++x) {
        uint64_t key = packCell(x, y, z);
        uint64_t b = mixBits(key) & mask;
        for (uint32_t i = bucketStart_[b]; i < bucketStart_[b + 1]; ++i)
          if (sortedKey_[i] == key && sortedOpl_[i] >= floor && squaredLength(sortedP_[i] - p) <= r2)
            out.push_back(order_[i]);
      }
}

size_t SurfacePhotonMap::memoryBytes() const {
  return sizeof(*this) + photons_.capacity() * sizeof(SurfacePhoton) + bucketStart_.capacity() * sizeof(uint32_t) +
         order_.capacity() * sizeof(uint32_t) + sortedP_.capacity() * sizeof(Point3f) +
         sortedKey_.capacity() * sizeof(uint64_t) + sortedOpl_.capacity() * sizeof(float);
}

}  // namespace femto::beams
