// BeamMap: a BVH over radius-inflated beam pieces (see beam_map.h).
//
// Why pieces: the box of a long diagonal beam is mostly empty space, so a
// camera ray crossing it is usually nowhere near the beam. Cutting the beam
// into pieces a few radii long keeps each box close to the beam's capsule
// (the surface area of the boxes per unit beam length, which is what a ray
// hit costs, is near its minimum for pieces of 2-6 radii). The pieces of one
// beam may all be hit by one segment; query() reports the beam once.
//
// Why a BVH of our own and not Embree's curves: plugins never see Embree
// (docs/STYLE.md, "Embree stays in the core"), and an all-hits query needs no
// closest-hit machinery.
#include <transient_beams/beam_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>

#include <tbb/parallel_invoke.h>

#include <femto/base/error.h>
#include <femto/base/thread_edges.h>
#include <femto/math/bbox.h>
#include <transient_beams/boundary_extension.h>
#include <transient_beams/ray_beam.h>

namespace femto::beams {

namespace {

// One beam piece: its radius-inflated box and the beam it belongs to.
struct Piece {
  BoundingBox3f box;
  uint32_t beam = 0;
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

constexpr int SahBins = 16;
// Below this depth SAH splits are used; beyond it the object median, which
// bounds the depth (and so the traversal stack) whatever the input.
constexpr int MaxSahDepth = 40;
constexpr int StackSize = 128;
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

// Depth-first copy of the reachable nodes (left child stays next to its
// parent), dropping the unused slots of the fixed-range layout.
uint32_t compact(const std::vector<Node>& sparse, uint32_t at, std::vector<Node>& dense) {
  uint32_t index = uint32_t(dense.size());
  dense.push_back(sparse[at]);
  if (sparse[at].count == 0) {
    compact(sparse, at + 1, dense);
    uint32_t right = compact(sparse, sparse[at].index, dense);
    dense[index].index = right;
  }
  return index;
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
  std::vector<Node> nodes;
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
      pieces.push_back(piece);
    }
  }
  if (!pieces.empty()) {
    std::vector<Node> sparse(2 * pieces.size() - 1);
    Builder(pieces, sparse, options).build(0, pieces.size(), 0, 0);
    compact(sparse, 0, impl->nodes);
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
  if (impl_) bytes += sizeof(Impl) + impl_->pieces.capacity() * sizeof(Piece) + impl_->nodes.capacity() * sizeof(Node);
  return bytes;
}

namespace {

// The camera segment prepared for slab tests against boxes.
struct SegmentSlabs {
  Point3f o;
  Vec3f invD;
  bool flat[3];  // direction component zero: inside the slab for all t or none
  float tMax;

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
};

}  // namespace

template <typename Report>
void BeamMap::traverse(const CameraSegment& segment, Report&& report) const {
  if (!impl_ || impl_->nodes.empty() || !(segment.tMax >= 0.0f)) return;
  // A NaN would make every slab test pass: a broken segment finds nothing.
  if (!isFinite(segment.ray.o) || !isFinite(segment.ray.d)) return;
  SegmentSlabs s;
  s.o = segment.ray.o;
  s.tMax = segment.tMax;
  for (int k = 0; k < 3; ++k) {
    s.flat[k] = segment.ray.d[k] == 0.0f;
    s.invD[k] = s.flat[k] ? 0.0f : 1.0f / segment.ray.d[k];
  }
  const Node* nodes = impl_->nodes.data();
  const Piece* pieces = impl_->pieces.data();
  // Children are tested before they are pushed, so only nodes the segment
  // crosses go through the stack (every popped node is a hit).
  if (!s.hits(nodes[0].lo, nodes[0].hi)) return;
  uint32_t stack[StackSize];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes[stack[--top]];
    if (node.count == 0) {
      const uint32_t left = uint32_t(&node - nodes) + 1, right = node.index;
      if (s.hits(nodes[right].lo, nodes[right].hi)) stack[top++] = right;
      if (s.hits(nodes[left].lo, nodes[left].hi)) stack[top++] = left;
      continue;
    }
    // A one-piece leaf's box is its piece's, already tested.
    for (uint32_t i = node.index; i < node.index + node.count; ++i)
      if (node.count == 1 || s.hits(pieces[i].box.min, pieces[i].box.max)) report(pieces[i]);
  }
}

void BeamMap::query(const CameraSegment& segment, std::vector<uint32_t>& out) const {
  out.clear();
  traverse(segment, [&](const Piece& piece) {
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
                              Cull cull) const {
  out.clear();
  if (marks.mark.size() != beams_.size() || marks.query == std::numeric_limits<uint32_t>::max()) {
    marks.mark.assign(beams_.size(), 0);
    marks.query = 0;
  }
  const uint32_t stamp = ++marks.query;
  uint32_t* mark = marks.mark.data();
  const bool lineCull = cull == Cull::Lines;
  size_t crossed = 0;
  const Beam* beams = beams_.data();
  traverse(segment, [&](const Piece& piece) {
    ++crossed;
    if (mark[piece.beam] == stamp) return;
    // Once per beam, whether it passes the line test or not. (A copy of the
    // beam's line in each piece, to test before the marks without reading the
    // beam, made the thick medium of the media suite 5 % slower: pieces of
    // 52 bytes instead of 28.)
    mark[piece.beam] = stamp;
    if (!lineCull || !linesFarApart(segment, beams[piece.beam], radius_)) out.push_back(piece.beam);
  });
  return crossed;
}

double BeamMap::crossingDensity(const std::vector<Beam>& beams, float radius,
                                const std::vector<CameraSegment>& segments, double weight) {
  if (beams.empty() || segments.empty() || !(weight > 0.0) || !std::isfinite(radius) || radius < 0.0f) return 0.0;
  std::vector<SegmentSlabs> slabs;
  for (const CameraSegment& segment : segments) {
    if (!(segment.tMax >= 0.0f) || !isFinite(segment.ray.o) || !isFinite(segment.ray.d)) continue;
    SegmentSlabs& s = slabs.emplace_back();
    s.o = segment.ray.o;
    s.tMax = segment.tMax;
    for (int k = 0; k < 3; ++k) {
      s.flat[k] = segment.ray.d[k] == 0.0f;
      s.invD[k] = s.flat[k] ? 0.0f : 1.0f / segment.ray.d[k];
    }
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
