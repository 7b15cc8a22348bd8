// femto_bench_rays: ray-casting and path-tracing throughput of the core.
// Not a test: it prints a Markdown table (tools/bench/run_ray_bench.sh turns
// it into docs/BENCHMARKS.md). For each scene (the Cornell box, and a ~100k
// triangle mesh: /work/shared/meshes/armadillo.obj when present, else a
// generated bumpy sphere) it measures, with 1 and 2 threads, the median of
// N runs of:
//   - femto Scene::rayIntersect on the camera's primary rays (with the full
//     SurfaceInteraction) and Scene::rayHitDistance (the hit only);
//   - raw Embree rtcIntersect1 on the same rays and the same triangles, with
//     the scene flags femto uses (robust) and with Embree's defaults;
//   - the scene's integrator (`path`) rendering the film, in samples/s.
// This tool links Embree directly (it is not a plugin) to have a baseline.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <femto/core/plugin.h>
#include <femto/math/pcg32.h>
#include <femto/render/mesh.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

using namespace femto;
namespace fs = std::filesystem;

namespace {

struct Options {
  bool quick = false;
  int runs = 5;
  int resolution = 512;  // primary rays: resolution^2 per run
  int pathResolution = 128;
  int pathSpp = 4;
  fs::path cornell = fs::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box/scene.xml";
  fs::path mesh = "/work/shared/meshes/armadillo.obj";
  std::vector<int> threads = {1, 2};
};

std::string fixed(double v, int digits = 2) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Median wall time and median process CPU time (all threads) of one run.
struct Timing {
  double wall = 0.0, cpu = 0.0;
};

double processCpuSeconds() {
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// Median times of `runs` calls of `work` inside an arena of `threads`
/// threads. CPU time is reported too: on a machine shared with other jobs the
/// wall time depends on the load, the CPU time per ray much less.
Timing medianTimes(int runs, int threads, const std::function<void()>& work) {
  tbb::task_arena arena(threads);
  std::vector<double> walls, cpus;
  arena.execute(work);  // warm-up (page faults, lazy TBB workers)
  for (int i = 0; i < runs; ++i) {
    double cpu0 = processCpuSeconds();
    auto start = std::chrono::steady_clock::now();
    arena.execute(work);
    walls.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    cpus.push_back(processCpuSeconds() - cpu0);
  }
  return {median(walls), median(cpus)};
}

/// Run `perRay(i)` for every ray index in parallel (grain: 1024 rays).
template <typename F>
void forEachRay(size_t count, F&& perRay) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1024), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) perRay(i);
  });
}

/// One primary ray per pixel centre (jittered) of a res x res image through the scene's camera.
std::vector<Ray> primaryRays(const Scene& scene, int res) {
  const Sensor& sensor = scene.sensor();
  Point2i size = sensor.film().size();
  PCG32 rng(1, 1);
  std::vector<Ray> rays;
  rays.reserve(size_t(res) * res);
  for (int y = 0; y < res; ++y)
    for (int x = 0; x < res; ++x) {
      Point2f film((x + rng.nextFloat()) * size.x / res, (y + rng.nextFloat()) * size.y / res);
      Ray ray;
      sensor.sampleRay(film, Point2f(0.5f, 0.5f), ray);
      rays.push_back(ray);
    }
  return rays;
}

/// The scene's triangles in a plain Embree scene (the baseline).
class RawEmbree {
 public:
  RawEmbree(const Scene& scene, bool robust) {
    device_ = rtcNewDevice(nullptr);
    scene_ = rtcNewScene(device_);
    if (robust) rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    for (const auto& shape : scene.shapes()) {
      const TriangleMesh* mesh = shape->asMesh();
      if (!mesh) continue;  // the benchmark scenes are all triangles
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), mesh->vertexCount()));
      for (const Point3f& p : mesh->positions()) *v++ = p.x, *v++ = p.y, *v++ = p.z;
      auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(uint32_t), mesh->triangleCount()));
      std::copy(mesh->indices().begin(), mesh->indices().end(), idx);
      rtcCommitGeometry(g);
      rtcAttachGeometry(scene_, g);
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(scene_);
  }
  ~RawEmbree() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  float distance(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = ray.o.x, rh.ray.org_y = ray.o.y, rh.ray.org_z = ray.o.z;
    rh.ray.dir_x = ray.d.x, rh.ray.dir_y = ray.d.y, rh.ray.dir_z = ray.d.z;
    rh.ray.tnear = ray.tmin, rh.ray.tfar = ray.tmax;
    rh.ray.mask = 0xFFFFFFFFu, rh.ray.flags = 0, rh.ray.time = 0.0f;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? Infinity : rh.ray.tfar;
  }

 private:
  RTCDevice device_;
  RTCScene scene_;
};

/// A UV sphere of `rings` x `segments` quads with a smooth radial bump
/// pattern (so the BVH is not trivially regular): 2 * rings * segments triangles.
std::shared_ptr<TriangleMesh> bumpySphere(int rings, int segments) {
  std::vector<Point3f> p;
  std::vector<uint32_t> idx;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      float theta = Pi * i / rings, phi = 2.0f * Pi * j / segments;
      float r = 1.0f + 0.08f * std::sin(7.0f * theta) * std::cos(5.0f * phi) + 0.03f * std::sin(23.0f * phi);
      p.emplace_back(r * std::sin(theta) * std::cos(phi), r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    }
  auto at = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
      idx.insert(idx.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  auto mesh = std::make_shared<TriangleMesh>(Properties("bumpy_sphere"));
  mesh->setGeometry(std::move(p), std::move(idx), {}, {}, Transform(), false, false);
  return mesh;
}

/// The mesh scene: the mesh framed by a camera on +z with a point light beside it.
std::shared_ptr<Scene> meshScene(const Options& opt, std::string& label) {
  std::shared_ptr<Shape> mesh;
  if (!opt.quick && fs::exists(opt.mesh)) {
    mesh = std::dynamic_pointer_cast<Shape>(loadObjectFromString(
        str("<shape type=\"obj\"><string name=\"filename\" value=\"", opt.mesh.string(), "\"/></shape>"), "."));
    label = opt.mesh.filename().string();
  } else {
    mesh = opt.quick ? bumpySphere(40, 80) : bumpySphere(224, 224);
    label = "generated bumpy sphere";
  }
  BoundingBox3f b = mesh->bbox();
  Point3f c = (b.min + b.max) * 0.5f;
  float r = 0.5f * length(b.max - b.min);
  Point3f eye = c + Vec3f(0.0f, 0.0f, 2.2f * r);
  Properties props("scene");
  props.setObject("mesh", mesh);
  props.setObject("sensor", loadObjectFromString(
      str("<sensor type=\"perspective\"><float name=\"fov\" value=\"45\"/>"
          "<transform name=\"to_world\"><lookat origin=\"", eye.x, ",", eye.y, ",", eye.z, "\" target=\"", c.x, ",",
          c.y, ",", c.z, "\" up=\"0,1,0\"/></transform>"
          "<sampler type=\"independent\"><integer name=\"sample_count\" value=\"", opt.pathSpp, "\"/></sampler>"
          "<film type=\"hdrfilm\"><integer name=\"width\" value=\"", opt.pathResolution,
          "\"/><integer name=\"height\" value=\"", opt.pathResolution, "\"/></film></sensor>"),
      "."));
  props.setObject("light", loadObjectFromString(str("<emitter type=\"point\"><point name=\"position\" value=\"",
                                                    eye.x + r, ",", eye.y + r, ",", eye.z, "\"/><rgb name=\"intensity\" value=\"",
                                                    4 * r * r, "\"/></emitter>"),
                                                "."));
  props.setObject("integrator", loadObjectFromString("<integrator type=\"path\"/>", "."));
  label += str(" (", mesh->asMesh()->triangleCount(), " triangles)");
  return std::make_shared<Scene>(props);
}

void benchScene(const std::string& label, const Scene& scene, const Options& opt) {
  std::vector<Ray> rays = primaryRays(scene, opt.resolution);
  RawEmbree robust(scene, true), plain(scene, false);
  std::vector<float> sink(rays.size());  // results are stored so nothing is optimised away
  double mrays = double(rays.size()) * 1e-6;
  double pathOneThread = 0.0, siOneThread = 0.0, pathCpuOneThread = 0.0, siCpuOneThread = 0.0;
  for (int threads : opt.threads) {
    Timing si = medianTimes(opt.runs, threads, [&] {
      forEachRay(rays.size(), [&](size_t i) {
        SurfaceInteraction its;
        sink[i] = scene.rayIntersect(rays[i], its) ? its.t + its.sh.n.x : -1.0f;
      });
    });
    Timing hit = medianTimes(opt.runs, threads, [&] {
      forEachRay(rays.size(), [&](size_t i) { sink[i] = scene.rayHitDistance(rays[i]); });
    });
    Timing embree = medianTimes(opt.runs, threads, [&] {
      forEachRay(rays.size(), [&](size_t i) { sink[i] = robust.distance(rays[i]); });
    });
    Timing embreeDefault = medianTimes(opt.runs, threads, [&] {
      forEachRay(rays.size(), [&](size_t i) { sink[i] = plain.distance(rays[i]); });
    });
    RenderOptions ro;
    ro.threads = threads;
    ro.progress = false;
    uint64_t samples = 0;
    Timing path = medianTimes(opt.runs, threads, [&] { samples = scene.integrator().render(scene, ro).samples; });
    double pathRate = double(samples) / path.wall * 1e-6, siRate = mrays / si.wall;
    if (threads == 1) pathOneThread = pathRate, siOneThread = siRate, pathCpuOneThread = path.cpu, siCpuOneThread = si.cpu;
    // Load-independent proxy of the speed-up on idle cores: n threads times
    // the ratio of CPU time for the same work (1 when threads add no overhead
    // per ray). Idle TBB workers spinning count against it.
    auto proxy = [&](double cpuOne, double cpuN) { return fixed(threads * cpuOne / cpuN); };
    auto percent = [](double x) { return str(std::lround(100.0 * x), " %"); };
    std::cout << "| " << label << " | " << threads << " | " << fixed(siRate) << " | " << fixed(mrays / hit.wall)
              << " | " << fixed(mrays / embree.wall) << " | " << fixed(mrays / embreeDefault.wall) << " | "
              << percent(embree.cpu / si.cpu) << " | " << percent(embree.cpu / hit.cpu) << " | " << fixed(pathRate, 3)
              << " | "
              << (threads == 1 ? std::string("-") : str(fixed(siRate / siOneThread), "x / ", fixed(pathRate / pathOneThread), "x"))
              << " | "
              << (threads == 1 ? std::string("-")
                               : str(proxy(siCpuOneThread, si.cpu), "x / ", proxy(pathCpuOneThread, path.cpu), "x"))
              << " |" << std::endl;
  }
}

void usage() {
  std::cout << "usage: femto_bench_rays [--quick] [--runs N] [--resolution N] [--mesh FILE.obj] [--cornell SCENE.xml]\n"
               "  --quick  tiny sizes, one run, generated mesh (a smoke test, a few seconds)\n";
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Error(str(a, " needs a value"));
      return argv[++i];
    };
    try {
      if (a == "--quick") opt.quick = true, opt.runs = 1, opt.resolution = 64, opt.pathResolution = 32, opt.pathSpp = 1;
      else if (a == "--runs") opt.runs = std::stoi(value());
      else if (a == "--resolution") opt.resolution = std::stoi(value());
      else if (a == "--mesh") opt.mesh = value();
      else if (a == "--cornell") opt.cornell = value();
      else if (a == "--help" || a == "-h") return usage(), 0;
      else throw Error(str("unknown argument \"", a, "\""));
    } catch (const std::exception& e) {
      std::cerr << "femto_bench_rays: " << e.what() << "\n";
      usage();
      return 2;
    }
  }
  try {
    std::cout << "Primary rays per run: " << opt.resolution << "x" << opt.resolution << "; path tracing: "
              << opt.pathResolution << "x" << opt.pathResolution << " pixels, " << opt.pathSpp
              << " spp; median of " << opt.runs << " runs.\n\n"
              << "| scene | threads | femto rayIntersect (Mrays/s) | femto rayHitDistance (Mrays/s) | "
                 "Embree robust (Mrays/s) | Embree default (Mrays/s) | rayIntersect / Embree (CPU time) | "
                 "rayHitDistance / Embree (CPU time) | path (Msamples/s) | wall speed-up rayIntersect / path | "
                 "CPU-time speed-up proxy rayIntersect / path |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    LoadOptions lo;
    lo.resolution = Point2i(opt.pathResolution, opt.pathResolution);
    lo.sampleCount = opt.pathSpp;
    auto cornell = loadScene(opt.cornell, lo);
    benchScene("Cornell box", *cornell, opt);
    std::string label;
    auto mesh = meshScene(opt, label);
    benchScene(label, *mesh, opt);
  } catch (const std::exception& e) {
    std::cerr << "femto_bench_rays: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
