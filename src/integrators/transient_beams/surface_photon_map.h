#pragma once
// Photons stored on surfaces, for transient photon mapping of surface
// transport (caustics and indirect light on walls, seen directly or through
// mirrors). Each photon remembers the OPL at which it arrived, so a density
// estimate at a camera hit deposits its energy at photon OPL + camera OPL.
// Immutable once built; queries are thread-safe.
#include <vector>

#include <femto/math/vector.h>
#include <femto/render/spectrum.h>

namespace femto::beams {

struct SurfacePhoton {
  Point3f p;           // where it landed
  Normal3f n;          // geometric normal of the surface, on the side the photon arrived from
  Vec3f wi;            // unit, from p back toward where the photon came from
  Color3f power{0.0f}; // flux carried
  double opl = 0.0;    // OPL at arrival since emission
};

class SurfacePhotonMap {
 public:
  SurfacePhotonMap() = default;
  explicit SurfacePhotonMap(std::vector<SurfacePhoton> photons);

  /// Indices of the photons within distance `radius` of `p` (exact; `out`
  /// is cleared first).
  void query(const Point3f& p, float radius, std::vector<uint32_t>& out) const;

  const std::vector<SurfacePhoton>& photons() const { return photons_; }
  size_t size() const { return photons_.size(); }

 private:
  std::vector<SurfacePhoton> photons_;
  // Acceleration structure chosen by the implementation (hash grid or kd-tree).
  std::vector<uint32_t> cellStart_, order_;
  Point3f gridMin_;
  float cellSize_ = 0.0f;
  int gridRes_[3] = {0, 0, 0};
};

}  // namespace femto::beams
