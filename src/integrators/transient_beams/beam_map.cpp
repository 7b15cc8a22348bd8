// BeamMap: a BVH over radius-inflated beam pieces (see beam_map.h).
//
// Why pieces: the box of a long diagonal beam is mostly empty space, so a
// camera ray crossing it is usually nowhere near the beam. Cutting the beam
// into pieces a few radii long keeps each box close to the beam's capsule
// (the surface area of the boxes per unit beam length, which is what a ray
// hit costs, is near its minimum for pieces of 2-6 radii). The pieces of one
// beam may all be hit by one segment; query() reports the beam once.
//
// Why four children per node: the build makes a binary tree (binned SAH);
// the queries walk a 4-wide one collapsed from it (Wald et al. 2008,
// "Getting rid of packets"; Dammertz et al. 2008, "Shallow bounding volume
// hierarchies"), whose four child boxes one SSE slab test checks at once and
// whose lanes hold single pieces where a leaf's pieces fit. The boxes are
// the binary tree's, so a segment meets the same pieces as before.
//
// Why a BVH of our own and not Embree's curves: plugins never see Embree
// (../shared/docs/STYLE.md, "Embree stays in the core"), and an all-hits query needs no
// closest-hit machinery.
#include <transient_beams/beam_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <tbb/parallel_invoke.h>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/math/bbox.h>
#include <transient_beams/boundary_extension.h>
#include <transient_beams/float_bounds.h>
#include <transient_beams/ray_beam.h>

namespace femto::beams {

namespace {

// One beam piece: its radius-inflated box and the beam it belongs to.
struct Piece {
  BoundingBox3f box;
  uint32_t beam = 0;
  /// Time gating: no pair found through this piece deposits later than
  /// (camera OPL at the segment's origin) + eta_c tMax + this (pieceOplBound).
  float oplMax = 0.0f;
};

// 32-byte node. Interior (count == 0): the left child is the next node, the
// right child is `index`. Leaf: pieces [index, index + count).
struct Node {
  Point3f lo;
  uint32_t index = 0;
  Point3f hi;
  uint32_t count = 0;
};
static_assert(sizeof(Node) == 32);

// The query's node: four child boxes in structure-of-arrays form (lo[k][i]:
// lane i's lower bound on axis k). A lane is an inner node (count 0, index =
// its Node4), a piece range [index, index + count) (count 1: the lane's box
// is the piece's own), or empty (count EmptyLane).
struct alignas(16) Node4 {
  float lo[3][4];
  float hi[3][4];
  uint32_t index[4];
  uint32_t count[4];
  float oplMax[4];  // the largest Piece::oplMax under each lane (time gating)
};
static_assert(sizeof(Node4) == 144);
constexpr uint32_t EmptyLane = std::numeric_limits<uint32_t>::max();

constexpr int SahBins = 16;
// Below this depth SAH splits are used; beyond it the object median, which
// bounds the depth (and so the traversal stack) whatever the input.
constexpr int MaxSahDepth = 40;
// The binary tree is at most MaxSahDepth + 32 levels deep (median splits
// below MaxSahDepth halve the pieces); each 4-wide level descends at least
// one of them and leaves at most three siblings on the stack.
constexpr int StackSize = 3 * (MaxSahDepth + 32) + 1;
// Subtrees larger than this are built in parallel.
constexpr size_t ParallelGrain = 4096;

float halfArea(const BoundingBox3f& b) {
  Vec3f e = b.extents();
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

// Builds the tree over pieces[begin, end) into nodes[base, base + 2n - 1):
// any binary tree over n pieces has at most 2n - 1 nodes, so each subtree
// owns a fixed index range and the two halves can be built in parallel
// without changing the result. The unused slots are dropped by compact().
class Builder {
 public:
  Builder(std::vector<Piece>& pieces, std::vector<Node>& nodes, const BeamMapOptions& options)
      : pieces_(pieces), nodes_(nodes), options_(options) {}

  void build(size_t begin, size_t end, size_t base, int depth) {
    BoundingBox3f bounds, centroids;
    for (size_t i = begin; i < end; ++i) {
      bounds.expand(pieces_[i].box);
      centroids.expand(pieces_[i].box.center());
    }
    Node& node = nodes_[base];
    node.lo = bounds.min;
    node.hi = bounds.max;
    size_t n = end - begin;
    if (n <= size_t(options_.maxLeafSize)) {
      node.index = uint32_t(begin);
      node.count = uint32_t(n);
      return;
    }
    size_t mid = split(begin, end, centroids, depth);
    size_t rightBase = base + 2 * (mid - begin);  // the left subtree uses at most 2 nL - 1 slots
    node.index = uint32_t(rightBase);
    node.count = 0;
    auto left = [&] { build(begin, mid, base + 1, depth + 1); };
    auto right = [&] { build(mid, end, rightBase, depth + 1); };
    if (n > ParallelGrain) {
      ForkJoinEdges edges;  // for ThreadSanitizer (base/thread_edges.h)
      tbb::parallel_invoke(edges.task(left), edges.task(right));
      edges.join();
    } else {
      left();
      right();
    }
  }

 private:
  // Reorders pieces[begin, end) and returns the first index of the right half
  // (strictly inside the range).
  size_t split(size_t begin, size_t end, const BoundingBox3f& centroids, int depth) {
    Vec3f ext = centroids.extents();
    int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : (ext.y >= ext.z ? 1 : 2);
    size_t mid = begin + (end - begin) / 2;
    auto center = [axis](const Piece& p) { return p.box.min[axis] + p.box.max[axis]; };
    if (ext[axis] > 0.0f && options_.split == BeamMapOptions::Split::Sah && depth < MaxSahDepth) {
      size_t sahMid = sahSplit(begin, end, centroids, axis);
      if (sahMid > begin && sahMid < end) return sahMid;
    }
    // Object median (also for coincident centroids, where any split is as
    // good): nth_element is deterministic for a given input order.
    std::nth_element(pieces_.begin() + begin, pieces_.begin() + mid, pieces_.begin() + end,
                     [&](const Piece& a, const Piece& b) { return center(a) < center(b); });
    return mid;
  }

  // Binned SAH (Wald 2007, "On fast construction of SAH-based bounding
  // volume hierarchies"): the plane between bins minimising
  // A_L n_L + A_R n_R. Returns begin when no plane separates the pieces.
  size_t sahSplit(size_t begin, size_t end, const BoundingBox3f& centroids, int axis) {
    std::array<BoundingBox3f, SahBins> binBox;
    std::array<size_t, SahBins> binCount{};
    float lo = centroids.min[axis];
    float scale = SahBins / (centroids.max[axis] - lo);
    auto binOf = [&](const Piece& p) {
      float c = 0.5f * (p.box.min[axis] + p.box.max[axis]);
      return std::clamp(int((c - lo) * scale), 0, SahBins - 1);
    };
    for (size_t i = begin; i < end; ++i) {
      int b = binOf(pieces_[i]);
      binBox[b].expand(pieces_[i].box);
      ++binCount[b];
    }
    // Sweep from the right, then from the left.
    std::array<float, SahBins> rightCost{};
    BoundingBox3f acc;
    size_t count = 0;
    for (int b = SahBins - 1; b > 0; --b) {
      acc.expand(binBox[b]);
      count += binCount[b];
      rightCost[b] = count ? halfArea(acc) * float(count) : 0.0f;
    }
    acc = BoundingBox3f();
    count = 0;
    float bestCost = Infinity;
    int bestPlane = -1;  // split between bins bestPlane and bestPlane + 1
    for (int b = 0; b < SahBins - 1; ++b) {
      acc.expand(binBox[b]);
      count += binCount[b];
      if (count == 0 || count == end - begin) continue;
      float cost = halfArea(acc) * float(count) + rightCost[b + 1];
      if (cost < bestCost) {
        bestCost = cost;
        bestPlane = b;
      }
    }
    if (bestPlane < 0) return begin;
    auto it = std::partition(pieces_.begin() + begin, pieces_.begin() + end,
                             [&](const Piece& p) { return binOf(p) <= bestPlane; });
    return size_t(it - pieces_.begin());
  }

  std::vector<Piece>& pieces_;
  std::vector<Node>& nodes_;
  const BeamMapOptions& options_;
};

// The 4-wide tree over the binary one (`binary`: left child next, right child
// at `index`). A node's lanes start as the binary node's two children; while
// a lane can be opened without exceeding four, the largest box is replaced by
// its children (an inner node) or its pieces (a leaf of at most the free
// lanes' count): the larger a box, the more segments cross it, and opening
// it lets those segments test its parts instead. Depth-first, so a node's
// subtree lies after it in memory.
struct Lane {
  enum class Kind { Inner, Leaf, Piece } kind;
  uint32_t at;  // binary node (Inner, Leaf) or piece index (Piece)
  BoundingBox3f box;
};

// The lane of binary node `at`.
Lane laneOf(const std::vector<Node>& binary, uint32_t at) {
  const Node& n = binary[at];
  return Lane{n.count == 0 ? Lane::Kind::Inner : Lane::Kind::Leaf, at, BoundingBox3f(n.lo, n.hi)};
}

uint32_t collapse(const std::vector<Node>& binary, const std::vector<Piece>& pieces, std::vector<Lane> lanes,
                  std::vector<Node4>& out) {
  for (;;) {
    int best = -1;
    float bestArea = -1.0f;
    for (int i = 0; i < int(lanes.size()); ++i) {
      const Lane& lane = lanes[i];
      const size_t opened = lane.kind == Lane::Kind::Inner  ? 2
                            : lane.kind == Lane::Kind::Leaf ? binary[lane.at].count
                                                            : 0;
      if (opened < 2 || lanes.size() - 1 + opened > 4) continue;
      const float area = halfArea(lane.box);
      if (area > bestArea) {
        bestArea = area;
        best = i;
      }
    }
    if (best < 0) break;
    const Lane open = lanes[best];
    lanes.erase(lanes.begin() + best);
    const Node& n = binary[open.at];
    if (open.kind == Lane::Kind::Inner) {
      lanes.insert(lanes.begin() + best, {laneOf(binary, open.at + 1), laneOf(binary, n.index)});
    } else {
      for (uint32_t i = 0; i < n.count; ++i)
        lanes.insert(lanes.begin() + best + i, Lane{Lane::Kind::Piece, n.index + i, pieces[n.index + i].box});
    }
  }
  const uint32_t self = uint32_t(out.size());
  out.emplace_back();
  for (int i = 0; i < 4; ++i) {
    uint32_t index = 0, count = EmptyLane;
    BoundingBox3f box(Point3f(0.0f), Point3f(0.0f));
    if (i < int(lanes.size())) {
      const Lane& lane = lanes[i];
      box = lane.box;
      if (lane.kind == Lane::Kind::Inner) {
        index = collapse(binary, pieces, {laneOf(binary, lane.at + 1), laneOf(binary, binary[lane.at].index)}, out);
        count = 0;
      } else if (lane.kind == Lane::Kind::Leaf) {
        index = binary[lane.at].index;
        count = binary[lane.at].count;
      } else {
        index = lane.at;
        count = 1;
      }
    }
    Node4& node = out[self];  // (out may have grown)
    for (int k = 0; k < 3; ++k) {
      node.lo[k][i] = box.min[k];
      node.hi[k][i] = box.max[k];
    }
    node.index[i] = index;
    node.count[i] = count;
  }
  return self;
}

/// Piece::oplMax for the piece of `beam` ending at parameter `end` (its
/// extension past the end included): a camera point x within the radius of
/// the piece lies within max(end, before r) + r of the beam's origin, and a
/// pair's OPL there (ray_beam.h, PairOpl: the continuation from the beam's
/// start, or the tilted wavefront) is at most beam.opl + (eta + |offsetDelay|)
/// times that. Rounded up to a float, with a margin for the rounding of the
/// pair's own OPL.
float pieceOplBound(const Beam& beam, float end, float radius) {
  const double od = std::sqrt(double(dot(beam.offsetDelay, beam.offsetDelay)));
  const double reach = std::max(double(end), double(beam.before) * radius) + double(radius);
  const double bound = beam.opl + (double(beam.eta) + od) * reach;
  return floatAtLeast(bound + 1e-5 * (std::abs(bound) + 1.0));
}

/// Fill Node4::oplMax bottom-up from node `at`; returns the node's largest.
float laneOplBounds(std::vector<Node4>& nodes, const std::vector<Piece>& pieces, uint32_t at) {
  float all = -std::numeric_limits<float>::infinity();
  for (int i = 0; i < 4; ++i) {
    const uint32_t count = nodes[at].count[i], index = nodes[at].index[i];
    float m = -std::numeric_limits<float>::infinity();
    if (count == 0)
      m = laneOplBounds(nodes, pieces, index);
    else if (count != EmptyLane)
      for (uint32_t p = index; p < index + count; ++p) m = std::max(m, pieces[p].oplMax);
    nodes[at].oplMax[i] = m;
    all = std::max(all, m);
  }
  return all;
}

void checkBeam(const Beam& beam, size_t index) {
  if (!isFinite(beam.origin) || !isFinite(beam.direction) || !std::isfinite(beam.length) || beam.length < 0.0f ||
      !(beam.before >= 0.0f && beam.before <= MaxBoundaryExtension) ||
      !(beam.after >= 0.0f && beam.after <= MaxBoundaryExtension) || !isFinite(beam.offsetDelay))
    throw Error(str("BeamMap: beam ", index, " has origin ", beam.origin, ", direction ", beam.direction,
                    " and length ", beam.length, "; expected finite values and a length >= 0"));
}

// Piece length. A piece of length L along the unit direction v, inflated by
// r, has a box of extents L |v_k| + 2 r and half area
//   H(L) = L^2 S2 + 4 r L S1 + 12 r^2,  S2 = |vx vy| + |vy vz| + |vz vx|,  S1 = |vx| + |vy| + |vz|.
// A beam of length l cut into l / L pieces costs the build about Cb per piece
// and the queries about Cq per crossing of a piece box, and a box of half
// area H is crossed rho H times (rho: BeamMapOptions::crossingDensity; for
// convex bodies in a uniform, isotropic field of lines the crossings are
// proportional to the surface area, Crofton/Cauchy). Per unit of beam
//   cost(L) = Cb / L + Cq rho (L S2 + 4 r S1 + 12 r^2 / L),
// smallest at L* = sqrt((12 r^2 + kappa^2) / S2), kappa^2 = (Cb / Cq) / rho:
// about 3.5 r on a diagonal beam when queries are many (kappa -> 0: the
// pieces of a few radii the map has always cut), longer where few segments
// pass, unbounded on axis-parallel beams (S2 = 0: their box is tight).
// Cb / Cq (PieceBuildCost): perf on the media suite's box with light outside
// gives ~250 ns per piece built (binned SAH, 2e5 pieces) and ~11 ns per box
// crossing (slab test, report, line test) there, a ratio of 22; where beams
// are many (the thick medium: 148k a pass) a crossing costs more, its beam
// and visit mark being cache misses. 10 is fitted on paired timings of the
// suite (1 thread, 4 passes): against 22 the thick medium 5 % faster, the box
// 2 % slower, the large medium and the fog box within noise; ~7 pieces per
// beam on the box, ~16 in the large medium, ~3 in the thick one.
constexpr double PieceBuildCost = 10.0;

// How many pieces each beam is cut into: ceil(extended length / L_i), L_i
// the fixed pieceLengthInRadii radii (crossingDensity 0) or L* above,
// lengthened uniformly until the total stays within maxPiecesPerBeam per beam
// on average.
std::vector<uint32_t> piecesPerBeam(const std::vector<Beam>& beams, float radius, const BeamMapOptions& options) {
  std::vector<uint32_t> counts(beams.size(), 1);
  const double fixedLength = double(options.pieceLengthInRadii) * radius;
  if (!(fixedLength > 0.0) || beams.empty()) return counts;
  const bool costRule = options.crossingDensity > 0.0 && std::isfinite(options.crossingDensity);
  const double r = radius, kappa2 = costRule ? PieceBuildCost / options.crossingDensity : 0.0;
  std::vector<double> lengths(beams.size(), fixedLength);
  if (costRule)
    for (size_t i = 0; i < beams.size(); ++i) {
      const Vec3f& v = beams[i].direction;
      const double x = std::abs(v.x), y = std::abs(v.y), z = std::abs(v.z);
      // S2 below 1e-12 (within 1e-6 rad of an axis): one piece, whatever the length.
      lengths[i] = std::sqrt((12.0 * r * r + kappa2) / std::max(x * y + y * z + z * x, 1e-12));
    }
  double scale = 1.0;
  const double budget = std::max(1.0, double(options.maxPiecesPerBeam)) * double(beams.size());
  for (int attempt = 0; attempt < 64; ++attempt) {
    double total = 0.0;
    for (size_t i = 0; i < beams.size(); ++i) {
      // Capped so a tiny radius cannot ask for billions of pieces.
      const double extended = double(beams[i].length) + double(beams[i].before + beams[i].after) * r;
      double want = std::min(std::ceil(extended / (lengths[i] * scale)), 1e6);
      counts[i] = uint32_t(std::max(1.0, want));
      total += counts[i];
    }
    if (total <= budget) return counts;
    // Rounding up per beam keeps the total above length / pieceLength: a
    // slightly larger step than the ratio converges in a few rounds.
    scale *= std::max(1.02, 1.02 * total / budget);
  }
  std::fill(counts.begin(), counts.end(), 1u);
  return counts;
}

}  // namespace

struct BeamMap::Impl {
  std::vector<Piece> pieces;
  std::vector<Node4> nodes;
};

namespace {

// Renumbers the beams in the order their first piece appears in the leaves
// (the pieces' order after the build). A query reads each candidate's beam
// for its line test; in the photons' order those reads land all over the
// beams (88 bytes each) and miss the cache: on the media suite's thick
// medium the load of the beam held 29 % of the query's samples. Neighbours
// in the tree are now neighbours in memory. The traversal order, and so
// every result, is unchanged; only the indices are.
void inLeafOrder(std::vector<Beam>& beams, std::vector<Piece>& pieces) {
  constexpr uint32_t Unplaced = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> index(beams.size(), Unplaced);
  std::vector<Beam> ordered;
  ordered.reserve(beams.size());
  for (Piece& piece : pieces) {
    uint32_t& i = index[piece.beam];
    if (i == Unplaced) {
      i = uint32_t(ordered.size());
      ordered.push_back(beams[piece.beam]);
    }
    piece.beam = i;
  }
  for (size_t b = 0; b < beams.size(); ++b)
    if (index[b] == Unplaced) ordered.push_back(beams[b]);  // (every beam has a piece; kept regardless)
  beams = std::move(ordered);
}

}  // namespace

BeamMap::BeamMap(std::vector<Beam> beams, float radius) : BeamMap(std::move(beams), radius, BeamMapOptions()) {}

BeamMap::BeamMap(std::vector<Beam> beams, float radius, const BeamMapOptions& options)
    : beams_(std::move(beams)), radius_(radius) {
  if (!std::isfinite(radius) || radius < 0.0f)
    throw Error(str("BeamMap: the kernel radius must be finite and >= 0, got ", radius));
  if (options.maxLeafSize < 1 || options.maxLeafSize > 16)
    throw Error(str("BeamMap: maxLeafSize must be in 1..16, got ", options.maxLeafSize));
  if (beams_.size() >= (size_t(1) << 31))
    throw Error(str("BeamMap: ", beams_.size(), " beams exceed the 2^31 a map can index"));
  for (size_t i = 0; i < beams_.size(); ++i) checkBeam(beams_[i], i);
  std::vector<uint32_t> counts = piecesPerBeam(beams_, radius, options);
  size_t total = 0;
  for (uint32_t c : counts) total += c;
  if (2 * total >= (size_t(1) << 32))
    throw Error(str("BeamMap: ", total, " beam pieces exceed the 2^31 a map can index; lower maxPiecesPerBeam"));

  auto impl = std::make_unique<Impl>();
  std::vector<Piece>& pieces = impl->pieces;
  pieces.reserve(total);
  for (size_t i = 0; i < beams_.size(); ++i) {
    const Beam& beam = beams_[i];
    // The kernel region, extensions past boundaries included (boundary_extension.h).
    const float lo = -beam.before * radius, hi = beam.length + beam.after * radius;
    for (uint32_t k = 0; k < counts[i]; ++k) {
      float t0 = lo + (hi - lo) * float(k) / float(counts[i]);
      float t1 = k + 1 == counts[i] ? hi : lo + (hi - lo) * float(k + 1) / float(counts[i]);
      Point3f a = beam.origin + beam.direction * t0, b = beam.origin + beam.direction * t1;
      // Pad by a few ulps of the coordinates: the points in between, as
      // rayBeamIntersect computes them, may round just outside [a, b].
      Vec3f pad = max(abs(a), abs(b)) * 4e-7f + Vec3f(radius * (1.0f + 1e-6f));
      Piece piece;
      piece.box = BoundingBox3f(a, b);
      piece.box.min -= pad;
      piece.box.max += pad;
      piece.beam = uint32_t(i);
      piece.oplMax = pieceOplBound(beam, t1, radius);
      pieces.push_back(piece);
    }
  }
  if (!pieces.empty()) {
    std::vector<Node> sparse(2 * pieces.size() - 1);
    Builder(pieces, sparse, options).build(0, pieces.size(), 0, 0);
    collapse(sparse, pieces, {laneOf(sparse, 0)}, impl->nodes);
    laneOplBounds(impl->nodes, pieces, 0);
    impl->nodes.shrink_to_fit();
    inLeafOrder(beams_, pieces);
  }
  impl_ = impl.release();
}

BeamMap::~BeamMap() { delete impl_; }

BeamMap::BeamMap(BeamMap&& o) noexcept : beams_(std::move(o.beams_)), radius_(o.radius_), impl_(o.impl_) {
  o.impl_ = nullptr;
}

BeamMap& BeamMap::operator=(BeamMap&& o) noexcept {
  if (this != &o) {
    delete impl_;
    beams_ = std::move(o.beams_);
    radius_ = o.radius_;
    impl_ = o.impl_;
    o.impl_ = nullptr;
  }
  return *this;
}

size_t BeamMap::pieceCount() const { return impl_ ? impl_->pieces.size() : 0; }
size_t BeamMap::nodeCount() const { return impl_ ? impl_->nodes.size() : 0; }

size_t BeamMap::memoryBytes() const {
  size_t bytes = sizeof(*this) + beams_.capacity() * sizeof(Beam);
  if (impl_) bytes += sizeof(Impl) + impl_->pieces.capacity() * sizeof(Piece) + impl_->nodes.capacity() * sizeof(Node4);
  return bytes;
}

namespace {

// The camera segment prepared for slab tests against boxes.
struct SegmentSlabs {
  Point3f o;
  Vec3f invD;
  bool flat[3];  // direction component (nearly) zero: inside the slab for all t or none
  float tMax;

  // A component below 1e-30 counts as zero: then 1 / d stays finite (no
  // inf * 0 = NaN below), and over any distance a scene spans (< 1e8) the
  // segment moves less than 1e-22 along that axis, far inside the boxes'
  // padding (the radius and a few ulps).
  explicit SegmentSlabs(const CameraSegment& segment) : o(segment.ray.o), tMax(segment.tMax) {
    for (int k = 0; k < 3; ++k) {
      flat[k] = std::abs(segment.ray.d[k]) < 1e-30f;
      invD[k] = flat[k] ? 0.0f : 1.0f / segment.ray.d[k];
    }
  }

  // Does o + t d, t in [0, tMax], meet the box [lo, hi] (closed)? A zero
  // direction component would give 0 * inf = NaN in the usual slab formula
  // when the origin lies on a face plane; it is tested directly instead.
  bool hits(const Point3f& lo, const Point3f& hi) const {
    float t0 = 0.0f, t1 = tMax;
    for (int k = 0; k < 3; ++k) {
      if (flat[k]) {
        if (o[k] < lo[k] || o[k] > hi[k]) return false;
        continue;
      }
      float a = (lo[k] - o[k]) * invD[k], b = (hi[k] - o[k]) * invD[k];
      t0 = std::max(t0, std::min(a, b));
      t1 = std::min(t1, std::max(a, b));
    }
    return t0 <= t1;
  }

  // hits() for the four boxes of a Node4 at once: bit i for lane i (empty
  // lanes included; the caller skips them). The same operations in the same
  // order as hits(), so the same answer: the boxes are finite and invD is
  // finite, so no NaN arises and SSE's min/max agree with std::min/max.
  unsigned hits4(const Node4& node) const {
#if defined(__SSE2__)
    __m128 t0 = _mm_setzero_ps(), t1 = _mm_set1_ps(tMax);
    __m128 inside = _mm_castsi128_ps(_mm_set1_epi32(-1));
    for (int k = 0; k < 3; ++k) {
      const __m128 lo = _mm_load_ps(node.lo[k]), hi = _mm_load_ps(node.hi[k]), ok = _mm_set1_ps(o[k]);
      if (flat[k]) {
        inside = _mm_and_ps(inside, _mm_and_ps(_mm_cmple_ps(lo, ok), _mm_cmpge_ps(hi, ok)));
        continue;
      }
      const __m128 inv = _mm_set1_ps(invD[k]);
      const __m128 a = _mm_mul_ps(_mm_sub_ps(lo, ok), inv), b = _mm_mul_ps(_mm_sub_ps(hi, ok), inv);
      t0 = _mm_max_ps(t0, _mm_min_ps(a, b));
      t1 = _mm_min_ps(t1, _mm_max_ps(a, b));
    }
    return unsigned(_mm_movemask_ps(_mm_and_ps(inside, _mm_cmple_ps(t0, t1))));
#else
    unsigned mask = 0;
    for (int i = 0; i < 4; ++i)
      if (hits(Point3f(node.lo[0][i], node.lo[1][i], node.lo[2][i]),
               Point3f(node.hi[0][i], node.hi[1][i], node.hi[2][i])))
        mask |= 1u << i;
    return mask;
#endif
  }
};

}  // namespace

template <typename Report>
void BeamMap::traverse(const CameraSegment& segment, float minOpl, Report&& report) const {
  if (!impl_ || impl_->nodes.empty() || !(segment.tMax >= 0.0f)) return;
  // A NaN would make every slab test pass: a broken segment finds nothing.
  if (!isFinite(segment.ray.o) || !isFinite(segment.ray.d)) return;
  const SegmentSlabs s(segment);
  const Node4* nodes = impl_->nodes.data();
  const Piece* pieces = impl_->pieces.data();
  uint32_t stack[StackSize];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node4& node = nodes[stack[--top]];
    unsigned mask = s.hits4(node);
    // Time gating: lanes whose pieces all deposit before minOpl.
    for (int i = 0; i < 4; ++i)
      if (!(node.oplMax[i] >= minOpl)) mask &= ~(1u << i);
    // Lanes in order 0..3, inner nodes pushed in reverse so that lane 0's
    // subtree is walked first: a fixed order, so deterministic results.
    for (int i = 3; i >= 0; --i)
      if ((mask >> i & 1u) && node.count[i] == 0) stack[top++] = node.index[i];
    for (int i = 0; i < 4; ++i) {
      if (!(mask >> i & 1u)) continue;
      const uint32_t count = node.count[i];
      if (count == 0 || count == EmptyLane) continue;
      // A one-piece lane's box is its piece's, already tested.
      const uint32_t first = node.index[i];
      for (uint32_t p = first; p < first + count; ++p)
        if (count == 1 || (pieces[p].oplMax >= minOpl && s.hits(pieces[p].box.min, pieces[p].box.max)))
          report(pieces[p]);
    }
  }
}

void BeamMap::query(const CameraSegment& segment, std::vector<uint32_t>& out) const {
  out.clear();
  traverse(segment, -std::numeric_limits<float>::infinity(), [&](const Piece& piece) {
    const uint32_t beam = piece.beam;
    // Neighbouring pieces of one beam often share a leaf or a subtree:
    // dropping repeats here shrinks the sort below.
    if (out.empty() || out.back() != beam) out.push_back(beam);
  });
  // Pieces of one beam may all be hit: report each beam once, ascending.
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

size_t BeamMap::queryUnsorted(const CameraSegment& segment, std::vector<uint32_t>& out, VisitMarks& marks,
                              Cull cull, double minOpl) const {
  out.clear();
  if (marks.mark.size() != beams_.size() || marks.query == std::numeric_limits<uint32_t>::max()) {
    marks.mark.assign(beams_.size(), 0);
    marks.query = 0;
  }
  const uint32_t stamp = ++marks.query;
  uint32_t* mark = marks.mark.data();
  size_t crossed = 0;
  // Rounded down to a float: never prunes a piece the double would keep.
  traverse(segment, floatAtMost(minOpl), [&](const Piece& piece) {
    ++crossed;
    if (mark[piece.beam] == stamp) return;
    mark[piece.beam] = stamp;
    out.push_back(piece.beam);
  });
  if (cull == Cull::Lines) {
    // The line test reads each candidate's beam, which is mostly not in the
    // cache (88 bytes each, a pass holds 10^4-10^5 of them). Done after the
    // traversal, over the list, the reads are independent of one another and
    // fetched a few candidates ahead. (A copy of the beam's line in each
    // piece, to test without reading the beam, made the thick medium of the
    // media suite 5 % slower: pieces of 52 bytes instead of 28.)
    constexpr size_t Ahead = 8;
    const Beam* beams = beams_.data();
    size_t kept = 0;
    for (size_t i = 0; i < out.size(); ++i) {
      if (i + Ahead < out.size()) __builtin_prefetch(&beams[out[i + Ahead]]);
      if (!linesFarApart(segment, beams[out[i]], radius_)) out[kept++] = out[i];
    }
    out.resize(kept);
  }
  return crossed;
}

double BeamMap::crossingDensity(const std::vector<Beam>& beams, float radius,
                                const std::vector<CameraSegment>& segments, double weight) {
  if (beams.empty() || segments.empty() || !(weight > 0.0) || !std::isfinite(radius) || radius < 0.0f) return 0.0;
  std::vector<SegmentSlabs> slabs;
  for (const CameraSegment& segment : segments) {
    if (!(segment.tMax >= 0.0f) || !isFinite(segment.ray.o) || !isFinite(segment.ray.d)) continue;
    slabs.emplace_back(segment);
  }
  // Every stride-th beam: at most 2048 boxes x the segments' slab tests.
  const size_t stride = (beams.size() + 2047) / 2048;
  double area = 0.0, crossings = 0.0;
  for (size_t i = 0; i < beams.size(); i += stride) {
    const Beam& beam = beams[i];
    const Point3f a = beam.origin - beam.direction * (beam.before * radius);
    const Point3f b = beam.origin + beam.direction * (beam.length + beam.after * radius);
    BoundingBox3f box(a, b);
    box.min -= Vec3f(radius);
    box.max += Vec3f(radius);
    if (!box.valid() || !isFinite(box.min) || !isFinite(box.max)) continue;
    area += halfArea(box);
    for (const SegmentSlabs& s : slabs) crossings += s.hits(box.min, box.max) ? 1.0 : 0.0;
  }
  return area > 0.0 ? weight * crossings / area : 0.0;
}

}  // namespace femto::beams
