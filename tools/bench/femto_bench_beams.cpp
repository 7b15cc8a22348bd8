// femto_bench_beams: build time and query throughput of the transient photon
// beams' BeamMap (src/integrators/transient_beams/beam_map.h) against beam
// count, kernel radius and the map's options, and against brute force
// (rayBeamIntersect with every beam). A tool, not a test:
// tools/bench/run_beam_bench.sh writes its table into docs/BENCHMARKS.md.
//
// Scene: beams of a homogeneous medium filling the unit cube (start uniform,
// direction uniform, length exponential with mean free path 0.25, clipped at
// the cube); camera segments cross the cube (start uniform inside, direction
// uniform, ending where they leave it).
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <femto/math/pcg32.h>
#include <transient_beams/beam_map.h>
#include <transient_beams/ray_beam.h>

using namespace femto;
using namespace femto::beams;

namespace {

double cpuSeconds(clockid_t clock) {
  timespec ts;
  clock_gettime(clock, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double wallSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

Vec3f randomDirection(PCG32& rng) {
  float z = 1.0f - 2.0f * rng.nextFloat(), phi = 2.0f * Pi * rng.nextFloat();
  float s = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

// Distance from p (inside the unit cube) along d to the cube's boundary.
float exitDistance(const Point3f& p, const Vec3f& d) {
  float t = Infinity;
  for (int k = 0; k < 3; ++k)
    if (d[k] != 0.0f) t = std::min(t, ((d[k] > 0 ? 1.0f : 0.0f) - p[k]) / d[k]);
  return t;
}

std::vector<Beam> makeBeams(size_t n, uint64_t seed) {
  PCG32 rng(seed, 1);
  std::vector<Beam> beams(n);
  for (Beam& b : beams) {
    b.origin = Point3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
    b.direction = randomDirection(rng);
    float free = -0.25f * std::log(1.0f - rng.nextFloat());
    b.length = std::max(1e-4f, std::min(free, exitDistance(b.origin, b.direction)));
    b.power = Color3f(1.0f);
  }
  return beams;
}

std::vector<CameraSegment> makeSegments(size_t n, uint64_t seed) {
  PCG32 rng(seed, 2);
  std::vector<CameraSegment> segs(n);
  for (CameraSegment& s : segs) {
    s.ray = Ray(Point3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()), randomDirection(rng));
    s.tMax = exitDistance(s.ray.o, s.ray.d);
  }
  return segs;
}

struct Variant {
  const char* name;
  BeamMapOptions options;
};

std::vector<Variant> variants() {
  std::vector<Variant> v;
  v.push_back({"default (pieces 4r, <=4/beam, SAH, leaf 8)", BeamMapOptions()});
  BeamMapOptions o;
  o.pieceLengthInRadii = 0.0f;
  v.push_back({"whole beams", o});
  o = BeamMapOptions();
  o.pieceLengthInRadii = 2.0f;
  o.maxPiecesPerBeam = 16.0f;
  v.push_back({"pieces 2r, <=16/beam", o});
  o = BeamMapOptions();
  o.pieceLengthInRadii = 8.0f;
  v.push_back({"pieces 8r, <=4/beam", o});
  o = BeamMapOptions();
  o.split = BeamMapOptions::Split::Median;
  v.push_back({"median split", o});
  o = BeamMapOptions();
  o.maxLeafSize = 1;
  v.push_back({"leaf 1", o});
  o = BeamMapOptions();
  o.maxLeafSize = 2;
  v.push_back({"leaf 2", o});
  o = BeamMapOptions();
  o.maxLeafSize = 4;
  v.push_back({"leaf 4", o});
  o = BeamMapOptions();
  o.maxLeafSize = 16;
  v.push_back({"leaf 16", o});
  return v;
}

// Queries `segs` (cycling) until `budget` seconds of this thread's CPU time
// have passed; returns queries per CPU second and the mean candidates and
// in-radius beams per query. `filter`: also run rayBeamIntersect on each
// candidate, as the integrator does.
struct QueryStats {
  double perSecond = 0, candidates = 0, inRadius = 0;
};

template <typename QueryFn>
QueryStats timeQueries(const std::vector<CameraSegment>& segs, double budget, size_t minQueries, QueryFn&& query) {
  QueryStats st;
  double t0 = cpuSeconds(CLOCK_THREAD_CPUTIME_ID), t;
  size_t n = 0, candidates = 0, inRadius = 0;
  do {
    for (int k = 0; k < 16; ++k, ++n) {
      auto [c, e] = query(segs[n % segs.size()]);
      candidates += c;
      inRadius += e;
    }
    t = cpuSeconds(CLOCK_THREAD_CPUTIME_ID) - t0;
  } while (t < budget || n < minQueries);
  st.perSecond = double(n) / t;
  st.candidates = double(candidates) / double(n);
  st.inRadius = double(inRadius) / double(n);
  return st;
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false, defaultOnly = false, bruteForce = true;
  std::vector<size_t> counts{10000, 100000, 1000000};
  std::vector<float> radii{0.01f, 0.05f};
  for (int i = 1; i < argc; ++i) {
    bool hasValue = i + 1 < argc;
    if (!std::strcmp(argv[i], "--quick")) {
      quick = true;
      counts = {2000};
      radii = {0.02f};
    } else if (!std::strcmp(argv[i], "--beams") && hasValue) {
      counts = {size_t(std::atoll(argv[++i]))};
    } else if (!std::strcmp(argv[i], "--radius") && hasValue) {
      radii = {float(std::atof(argv[++i]))};
    } else if (!std::strcmp(argv[i], "--default-only")) {
      defaultOnly = true;
    } else if (!std::strcmp(argv[i], "--no-brute-force")) {
      bruteForce = false;
    } else {
      std::fprintf(stderr,
                   "usage: femto_bench_beams [--quick] [--beams N] [--radius R] [--default-only] [--no-brute-force]\n");
      return 2;
    }
  }
  double budget = quick ? 0.02 : 0.4;
  std::vector<CameraSegment> segs = makeSegments(4096, 99);

  std::printf("| beams | radius | map | build wall (s) | build CPU (s) | pieces / beam | nodes | memory (MB) |"
              " queries / CPU s (query only) | candidates / query | within radius / query | candidates / within |"
              " queries / CPU s (query + rayBeamIntersect) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (size_t n : counts) {
    std::vector<Beam> beams = makeBeams(n, 7);
    for (float radius : radii) {
      std::vector<Variant> all = variants();
      if (defaultOnly) all.resize(1);
      for (const Variant& v : all) {
        double w0 = wallSeconds(), c0 = cpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
        BeamMap map(beams, radius, v.options);
        double buildWall = wallSeconds() - w0, buildCpu = cpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - c0;
        std::vector<uint32_t> out;
        QueryStats q = timeQueries(segs, budget, 64, [&](const CameraSegment& s) {
          map.query(s, out);
          return std::pair<size_t, size_t>(out.size(), 0);
        });
        RayBeamHit hit;
        QueryStats f = timeQueries(segs, budget, 64, [&](const CameraSegment& s) {
          map.query(s, out);
          size_t within = 0;
          for (uint32_t i : out) within += rayBeamIntersect(s, map.beams()[i], radius, hit);
          return std::pair<size_t, size_t>(out.size(), within);
        });
        std::printf("| %zu | %.2f | %s | %.3f | %.3f | %.2f | %zu | %.1f | %.0f | %.1f | %.1f | %.2f | %.0f |\n", n,
                    radius, v.name, buildWall, buildCpu, double(map.pieceCount()) / double(n), map.nodeCount(),
                    double(map.memoryBytes()) / (1 << 20), q.perSecond, q.candidates, f.inRadius,
                    f.inRadius > 0 ? f.candidates / f.inRadius : 0.0, f.perSecond);
        std::fflush(stdout);
      }
      if (!bruteForce) continue;
      // Brute force: every beam through rayBeamIntersect.
      RayBeamHit hit;
      QueryStats b = timeQueries(segs, budget, 16, [&](const CameraSegment& s) {
        size_t within = 0;
        for (const Beam& beam : beams) within += rayBeamIntersect(s, beam, radius, hit);
        return std::pair<size_t, size_t>(n, within);
      });
      std::printf("| %zu | %.2f | brute force (rayBeamIntersect with every beam) | - | - | - | - | %.1f | - | - | %.1f | - | %.1f |\n",
                  n, radius, double(beams.size() * sizeof(Beam)) / (1 << 20), b.inRadius, b.perSecond);
      std::fflush(stdout);
    }
  }
  return 0;
}
