// femto_bench_ray_beam: cost of one ray x beam estimate (rayBeamIntersect),
// the innermost loop of transient photon beams (run once per candidate pair
// the beam map returns). Not a test: prints ns per call for candidate-like
// pairs (beam within a few radii of the segment, as a BVH query returns them),
// a tenth of them near-parallel, for both kernels. Usage:
//   femto_bench_ray_beam [pairs]   (default 20000, cache-resident like the
//   candidates of one query batch; each run loops over them 50 times)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include <femto/math/pcg32.h>
#include <transient_beams/ray_beam.h>

using namespace femto;
using namespace femto::beams;

namespace {

Vec3f randomDirection(PCG32& rng) {
  float z = 2 * rng.nextFloat() - 1, phi = 2 * Pi * rng.nextFloat(), s = std::sqrt(std::max(0.0f, 1 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

struct Candidate {
  CameraSegment segment;
  Beam beam;
};

/// Camera segments of length 1..3 and beams of length 0.1..2 whose closest
/// points lie within 3 radii (so roughly a third are hits).
std::vector<Candidate> candidates(int n, float radius) {
  PCG32 rng(1, 2);
  std::vector<Candidate> out(static_cast<size_t>(n));
  for (Candidate& c : out) {
    c.segment.ray = Ray({0, 0, 0}, randomDirection(rng));
    c.segment.tMax = 1 + 2 * rng.nextFloat();
    Vec3f v = rng.nextFloat() < 0.1f ? normalize(c.segment.ray.d + randomDirection(rng) * 1e-3f) : randomDirection(rng);
    c.beam.direction = v;
    c.beam.length = 0.1f + 1.9f * rng.nextFloat();
    Point3f near = c.segment.ray(c.segment.tMax * rng.nextFloat()) + randomDirection(rng) * (3 * radius * rng.nextFloat());
    c.beam.origin = near - v * (c.beam.length * rng.nextFloat());
  }
  return out;
}

/// This thread's CPU time in ns: the machine is often shared (parallel
/// builds), and wall time would count other processes' slices.
double threadNs() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

double nsPerCall(const std::vector<Candidate>& pairs, float radius, RayBeamKernel kernel, int& hits) {
  std::vector<double> runs;
  for (int run = 0; run < 5; ++run) {
    double t0 = threadNs();
    double sink = 0;
    hits = 0;
    RayBeamHit h;
    for (int repeat = 0; repeat < 50; ++repeat) {
      hits = 0;
      for (const Candidate& c : pairs) {
        if (rayBeamIntersect(c.segment, c.beam, radius, h, kernel)) ++hits, sink += h.kernel + h.oplEnd;
      }
    }
    double t1 = threadNs();
    if (sink < 0) std::printf("impossible\n");  // keeps the loop alive
    runs.push_back((t1 - t0) / (50.0 * double(pairs.size())));
  }
  std::sort(runs.begin(), runs.end());
  return runs[runs.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20000;
  const float radius = 0.02f;
  std::vector<Candidate> pairs = candidates(n, radius);
  std::printf("| kernel | pairs | hits | thread CPU ns / call (median of 5) |\n|---|---|---|---|\n");
  for (RayBeamKernel k : {RayBeamKernel::OneD, RayBeamKernel::Cylinder}) {
    int hits = 0;
    double ns = nsPerCall(pairs, radius, k, hits);
    std::printf("| %s | %d | %d | %.1f |\n", k == RayBeamKernel::OneD ? "1D" : "cylinder", n, hits, ns);
  }
  return 0;
}
