#pragma once
// Photons stored on surfaces, for transient photon mapping of surface
// transport (caustics and indirect light on walls, seen directly or through
// mirrors). Each photon remembers the OPL at which it arrived, so a density
// estimate at a camera hit deposits its energy at photon OPL + camera OPL.
// Immutable once built; queries are thread-safe.
//
// Structure: a hashed uniform grid (Teschner et al. 2003, "Optimized spatial
// hashing for collision detection of deformable objects"): photons sorted by
// cell, cells hashed into a table of about two buckets per photon, so memory
// is linear in the photon count however fine the grid. A query visits the
// cells its sphere overlaps; it is cheapest when the cell size is about the
// query radius, so pass the radius you will query with when you know it.
#include <cstdint>
#include <limits>
#include <vector>

#include <femto/math/spectrum.h>
#include <femto/math/vector.h>

namespace femto::beams {

struct SurfacePhoton {
  Point3f p;             // where it landed
  Normal3f n;            // geometric normal of the surface, on the side the photon arrived from
  Vec3f wi;              // unit, from p back toward where the photon came from
  Color3f power{0.0f};   // flux carried
  double opl = 0.0;      // OPL at arrival since emission
  int depth = 1;         // photon path segments up to this point (1: straight from the emitter)
  uint32_t emitter = 0;  // index in Scene::emitters() of the emitter that sent the photon (its pulse)
  // The photon's last leg, straight at index legEta from the point
  // p + wi * leg (its last vertex, scattering or boundary) to p; the camera
  // side times a gather at another point through that vertex
  // (lastLegDelay). legEta 0: not known, no correction; an infinite leg: a
  // plane wave.
  float leg = 0.0f;
  float legEta = 0.0f;
};

/// OPL to add to `photon.opl` for light that took the photon's path but
/// ended its last leg at `x` instead of at photon.p: eta (|x - q| - leg), q the
/// leg's start; exactly the OPL of that path, so a gather at x never
/// deposits before light can arrive there (any path's OPL is at least the
/// shortest's; an infinite leg, a plane wave, is the limit). Without it the estimate at x would be the photons' times
/// at up to a radius away: a blur of the time profile of width up to 2 eta r (a wavefront crossing the disc). What is
/// left is the spread of the last vertices' positions the disc averages over, second order: eta |x - p|^2 / (2 leg)
/// across the leg.
double lastLegDelay(const SurfacePhoton& photon, const Point3f& x);

class SurfacePhotonMap {
 public:
  SurfacePhotonMap() = default;
  /// Cell size guessed from the photons alone: photons lie on surfaces, so
  /// cells are sized for about 8 photons each on a surface spanning the
  /// photons' bounding box. Prefer the constructor below when the query
  /// radius is known.
  explicit SurfacePhotonMap(std::vector<SurfacePhoton> photons);
  /// Cell size = `queryRadius` (> 0, finite), enlarged only if the grid
  /// would need more than 2^21 cells along an axis. Throws femto::Error for
  /// a bad radius or a photon with a non-finite position.
  SurfacePhotonMap(std::vector<SurfacePhoton> photons, float queryRadius);

  /// Indices of the photons within distance `radius` of `p` (exact:
  /// squaredLength(x - p) <= radius * radius; each once, in an order fixed by
  /// the map and `p`; `out` is cleared first). Any radius works; radii
  /// much larger than the cell size cost more cells per query.
  ///
  /// Time gating: with `minOpl` finite, photons whose light cannot reach p
  /// at or after minOpl are skipped: opl + legEta radius < minOpl
  /// (lastLegDelay is at most legEta |x - p|). Every photon that can is
  /// still reported.
  void query(const Point3f& p, float radius, std::vector<uint32_t>& out,
             double minOpl = -std::numeric_limits<double>::infinity()) const;

  const std::vector<SurfacePhoton>& photons() const { return photons_; }
  size_t size() const { return photons_.size(); }
  float cellSize() const { return cellSize_; }
  /// Bytes held (photons and grid), for memory reports.
  size_t memoryBytes() const;

 private:
  void build(float cellSize);
  uint64_t cellKey(const Point3f& p) const;

  std::vector<SurfacePhoton> photons_;
  // Photons sorted by bucket: bucket b holds sorted entries
  // [bucketStart_[b], bucketStart_[b + 1]); each entry keeps its photon's
  // index, position and cell key (to skip other cells sharing the bucket).
  std::vector<uint32_t> bucketStart_, order_;
  std::vector<Point3f> sortedP_;
  std::vector<uint64_t> sortedKey_;
  std::vector<float> sortedOpl_;  // the photons' OPL, rounded up (time gating)
  float maxLegEta_ = 0.0f;         // the largest legEta
  Point3f gridMin_;
  float cellSize_ = 0.0f;
  int gridRes_[3] = {0, 0, 0};  // cells along each axis covering the photons
};

}  // namespace femto::beams
