#pragma once
// The beam map: every beam of one photon pass in an acceleration structure
// that finds the beams a camera segment may pass within the kernel radius of.
// Immutable once built; queries are thread-safe.
//
// Structure: a bounding volume hierarchy over beam *pieces* (long beams are
// cut into pieces of bounded length so that each piece's axis-aligned box,
// the piece inflated by the radius, stays close to the beam's capsule; how
// long: a fixed number of radii, or a cost rule weighing the build against
// the crossings the queries will make, BeamMapOptions::crossingDensity),
// built with a binned surface area heuristic. Choices measured in
// docs/BENCHMARKS.md ("Beam map") and docs/design/photon-beams.md ("Culling:
// the line test"); the build is parallel but deterministic (same beams, same tree).
#include <cstdint>
#include <limits>
#include <vector>

#include <transient_beams/beam.h>
#include <transient_beams/ray_beam.h>

namespace femto::beams {

/// Tuning knobs of the beam map. The defaults are the measured choice
/// (docs/BENCHMARKS.md, "Beam map"); the benchmark varies them.
struct BeamMapOptions {
  /// Beams longer than this many kernel radii are cut into pieces of about
  /// this length. 0 = never cut.
  float pieceLengthInRadii = 4.0f;
  /// Memory bound: on average at most this many pieces per beam; when the
  /// cut above would exceed it, all pieces are lengthened uniformly.
  float maxPiecesPerBeam = 4.0f;
  /// Pieces per BVH leaf (1..16).
  int maxLeafSize = 8;
  /// Split rule: binned surface area heuristic, or the object median along
  /// the widest centroid axis.
  enum class Split { Sah, Median } split = Split::Sah;
  /// How many times query segments will cross a piece box per unit of its
  /// half surface area over the map's life (crossingDensity() estimates it).
  /// 0: unknown, and every beam is cut into pieces of pieceLengthInRadii
  /// radii. > 0: each beam's pieces get the length that minimises the cost of
  /// building them plus the cost of the crossings their boxes will take
  /// (beam_map.cpp, "Piece length"): long where few segments pass or where
  /// the beam runs along an axis (its boxes are tight at any length), down to
  /// about 3.5 radii on diagonal beams that many segments cross.
  /// maxPiecesPerBeam still bounds the total.
  double crossingDensity = 0.0;
};

class BeamMap {
 public:
  /// Builds the structure over `beams`, each inflated by `radius`. Throws
  /// femto::Error for a negative or non-finite radius, or a beam with a
  /// non-finite origin/direction or a negative or non-finite length.
  BeamMap(std::vector<Beam> beams, float radius);
  BeamMap(std::vector<Beam> beams, float radius, const BeamMapOptions& options);
  ~BeamMap();
  BeamMap(BeamMap&&) noexcept;
  BeamMap& operator=(BeamMap&&) noexcept;

  /// Indices (into beams()) of the beams whose radius-inflated bounds the
  /// segment crosses: a superset of the beams within `radius`, each at most
  /// once, in ascending order. `out` is cleared first. The segment is
  /// ray.o + t ray.d for t in [0, tMax] (ray.tmin/tmax are ignored); tMax may
  /// be infinite; a NaN or negative tMax finds nothing.
  void query(const CameraSegment& segment, std::vector<uint32_t>& out) const;

  /// Per-thread scratch of the unsorted query below: one visit mark per beam.
  struct VisitMarks {
    std::vector<uint32_t> mark;  // the query that last reported beam i
    uint32_t query = 0;
  };
  /// What queryUnsorted reports of the beams whose piece boxes a segment crosses.
  enum class Cull {
    /// All of them: query()'s beams.
    Boxes,
    /// Only those whose axis the segment's line may pass within the radius
    /// of: the lines' distance (ray_beam.h, linesFarApart, conservative
    /// against rayBeamIntersect's first test), once per beam, at half that
    /// test's cost. The beams returned are then those near the segment's
    /// line, not all those near a box (for a long beam at a small radius the
    /// box of a piece is mostly empty space).
    Lines,
  };
  /// The same beams as query() (or, with Cull::Lines, those of them near the
  /// segment's line), each once, but in traversal order (fixed by the map and
  /// the segment, so deterministic), deduplicated with `marks` instead of a
  /// sort: O(candidates) instead of O(candidates log candidates), which
  /// matters when a segment meets hundreds of beams (the camera side's hot
  /// loop). `marks` is sized on first use. Returns how many piece boxes the
  /// segment crossed (the map's work; statistics).
  ///
  /// Time gating: with `minOpl` finite, pieces none of whose pairs can
  /// deposit at or after (camera OPL at the segment's origin) + eta_c tMax +
  /// minOpl are skipped (each piece and BVH lane keeps the bound, beam_map.cpp
  /// pieceOplBound). Every beam with a pair that deposits later is still
  /// reported; beams whose pairs all deposit earlier may be, or not.
  size_t queryUnsorted(const CameraSegment& segment, std::vector<uint32_t>& out, VisitMarks& marks,
                       Cull cull = Cull::Boxes, double minOpl = -std::numeric_limits<double>::infinity()) const;

  /// BeamMapOptions::crossingDensity for `beams` at `radius` from sample
  /// segments standing for the queries, each for `weight` real ones (probe
  /// camera segments: weight = camera samples per probe ray): crossings of
  /// the segments with the boxes of up to 2048 of the beams (whole, inflated
  /// by the radius) per unit of those boxes' half area, times the weight.
  /// Deterministic; 0 without segments or beams.
  static double crossingDensity(const std::vector<Beam>& beams, float radius,
                                const std::vector<CameraSegment>& segments, double weight);

  /// The beams, in the map's order (the first piece of each in leaf order,
  /// not the order given: neighbours in the tree lie together in memory).
  const std::vector<Beam>& beams() const { return beams_; }
  float radius() const { return radius_; }
  /// Bytes held by the structure (beams and nodes), for memory reports.
  size_t memoryBytes() const;
  /// Number of pieces the beams were cut into, and of BVH nodes (statistics).
  size_t pieceCount() const;
  size_t nodeCount() const;

 private:
  struct Impl;
  std::vector<Beam> beams_;
  float radius_ = 0.0f;
  Impl* impl_ = nullptr;

  /// Calls report(piece) for every piece whose box the segment crosses (a
  /// beam once per piece hit), in traversal order.
  /// (and whose OPL bound is at least `minOpl`)
  template <typename Report>
  void traverse(const CameraSegment& segment, float minOpl, Report&& report) const;
};

}  // namespace femto::beams
