#pragma once
// The beam map: every beam of one photon pass in an acceleration structure
// that finds the beams a camera segment may pass within the kernel radius of.
// Immutable once built; queries are thread-safe.
#include <cstdint>
#include <vector>

#include <transient_beams/beam.h>

namespace femto::beams {

class BeamMap {
 public:
  /// Builds the structure over `beams`, each inflated by `radius`.
  BeamMap(std::vector<Beam> beams, float radius);
  ~BeamMap();
  BeamMap(BeamMap&&) noexcept;
  BeamMap& operator=(BeamMap&&) noexcept;

  /// Indices (into beams()) of the beams whose radius-inflated bounds the
  /// segment crosses: a superset of the beams within `radius`, each at most
  /// once, in ascending order. `out` is cleared first.
  void query(const CameraSegment& segment, std::vector<uint32_t>& out) const;

  const std::vector<Beam>& beams() const { return beams_; }
  float radius() const { return radius_; }
  /// Bytes held by the structure (beams and nodes), for memory reports.
  size_t memoryBytes() const;

 private:
  struct Impl;
  std::vector<Beam> beams_;
  float radius_ = 0.0f;
  Impl* impl_ = nullptr;
};

}  // namespace femto::beams
