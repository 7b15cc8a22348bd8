// transient_nlos_path: mitransient's path tracer for non-line-of-sight (NLOS)
// captures (Royo et al., "Non-line-of-sight transient rendering", Computers &
// Graphics 107, 2022). It renders with an nlos_capture_meter (each camera
// ray runs from the sensor to a point on the relay wall) or with any camera
// that sees the wall, the laser then a projector the scene places, as
// mitransient's NLOS example has it (every contribution keeps its first and
// last legs, and every shape is hidden geometry: there is no relay wall to
// tell apart); from the wall paths
// bounce into the hidden scene and back, lit only by the laser (a projector
// with a tiny fov aimed at a wall point, aimed_laser.h). Every contribution is
// recorded at its exact optical path length with the laser's pulse, as
// transient_path does. At each surface vertex: next-event estimation to the
// laser, laser sampling (nlos_laser_sampling: connect to the spot a laser ray
// lights, unbiased for any spot size; next-event estimation then only at the
// first vertex) and BSDF or hidden-geometry directions (hidden_geometry.h).
// The estimators' formulas and how they share paths:
// docs/design/transient-nlos-path.md; the parameters in the user's words:
// docs/nlos.md, "Parameters". Depth counts segments (the third bounce sensor
// -> wall -> hidden object -> wall -> laser has 4). Deterministic for a seed
// whatever the thread count (per-pixel sampler streams, no integrator state).
//
// clang-format off
// | name                 | type    | default | meaning                                                     | unit |
// |----------------------|---------|---------|-------------------------------------------------------------|------|
// | max_depth            | integer | 6       | longest path in segments (-1: no limit); mitransient's default | - |
// | rr_depth             | integer | 5       | depth from which Russian roulette may end paths             | -    |
// | filter_depth         | integer | -1      | record only paths of exactly this many segments (-1: all)   | -    |
// | filter_bounces       | integer | -1      | mitransient's other spelling: filter_depth = filter_bounces + 1 | - |
// | discard_direct_paths | boolean | false   | drop the 2-segment paths sensor -> wall -> laser           | -    |
// | nlos_laser_sampling  | boolean | false   | connect each vertex to the spot the laser lights            | -    |
// | nlos_hidden_geometry_sampling | boolean | false | sample directions toward the hidden geometry        | -    |
// | nlos_hidden_geometry_sampling_do_rroulette | boolean | false | choose hidden-geometry or BSDF sampling at random (1/2 each) | - |
// | nlos_hidden_geometry_sampling_includes_relay_wall | boolean | false | the relay wall counts as hidden geometry | - |
// | account_first_and_last_bounces | boolean | true | through a camera: keep the camera-to-wall and laser-to-wall legs in the OPL (false removes both; with a capture meter, give it there) | - |
// | temporal_filter      | string  | ""      | the film's time filter: "" (the film's own), "box", "gaussian" | - |
// | gaussian_stddev      | float   | 2       | its standard deviation                                      | bins |
// | block_size           | integer | 0       | mitransient's tile size: accepted, ignored (femto picks its tiles) | - |
// clang-format on
#include <cmath>

#include <femto/core/plugin.h>
#include <femto/lights/oriented_point_emitter.h>
#include <femto/render/bsdf.h>
#include <femto/render/nlos_sensor.h>
#include <femto/render/path_depth.h>
#include <femto/render/sampler.h>
#include <femto/render/scene.h>
#include <femto/render/transient_integrator.h>

#include "aimed_laser.h"
#include "hidden_geometry.h"

namespace femto {
namespace {

/// One camera path: where it is, its OPL there and what it carries.
struct NlosPath {
  SurfaceInteraction si;
  double opl = 0.0;    // OPL from the sensor to si.p
  Color3f beta{1.0f};  // throughput
  int segments = 1;    // the camera segment
  float eta = 1.0f;    // refractive index where the path is (inside a dielectric: the product of its refractions)
};

/// What every contribution of one camera sample shares.
struct Capture {
  const AimedLaser& laser;
  double oplShift;  // subtracted from every OPL (account_first_and_last_bounces = false)
  RadianceRecorder& recorder;
};

}  // namespace

class TransientNlosPath final : public TransientIntegrator {
 public:
  explicit TransientNlosPath(const Properties& props) : depth_(PathDepthSettings::read(props, 6)) {
    filterDepth_ = int(props.getInt("filter_depth", -1, -1, 1 << 20));
    if (props.has("filter_bounces")) {
      if (props.has("filter_depth"))
        props.raise("filter_bounces", "give either filter_depth or filter_bounces, not both");
      filterDepth_ = int(props.getInt("filter_bounces", -1, -1, 1 << 20));
      if (filterDepth_ >= 0) ++filterDepth_;
    }
    discardDirect_ = props.getBool("discard_direct_paths", false);
    laserSampling_ = props.getBool("nlos_laser_sampling", false);
    hiddenSampling_ = props.getBool("nlos_hidden_geometry_sampling", false);
    hiddenRoulette_ = props.getBool("nlos_hidden_geometry_sampling_do_rroulette", false) && hiddenSampling_;
    hiddenIncludesWall_ = props.getBool("nlos_hidden_geometry_sampling_includes_relay_wall", false) && hiddenSampling_;
    if (props.has("account_first_and_last_bounces")) keepLegs_ = props.getBool("account_first_and_last_bounces");
    readTemporalFilter(props);
    props.getInt("block_size", 0);  // mitransient's tile size in scalar mode: femto picks its own tiles
  }

  /// The laser nested in the capture meter is this integrator's light (laserOf).
  bool tracesNestedLaser() const override { return true; }

  /// Checks the set-up once, before any tile runs, so a wrong scene fails
  /// with one message instead of rendering black.
  RenderStats render(const Scene& scene, const RenderOptions& options) const override {
    if (!dynamic_cast<const NlosSensor*>(&scene.sensor())) return renderThroughCamera(scene, options);
    if (keepLegs_)
      throw Error(str(toString(), ": account_first_and_last_bounces is the nlos_capture_meter's parameter when "
                                  "the scene has one: give it there"));
    const NlosSensor& sensor = *dynamic_cast<const NlosSensor*>(&scene.sensor());
    const Emitter& emitter = laserOf(scene, sensor);
    if (!emitter.isDelta())
      throw Error(str(toString(), ": the laser must be a light at a point (a projector with a small fov), not ",
                      emitter.toString()));
    Ray probe;
    sensor.sampleRay(Point2f(0.5f), Point2f(0.5f), probe);  // places the wall points (errors name the wall)
    sensor.laserTarget(sensor.relayWall().bbox().center());
    if (hiddenSampling_ && HiddenGeometry(scene, &sensor.relayWall(), hiddenIncludesWall_).empty())
      throw Error(str(toString(),
                      ": nlos_hidden_geometry_sampling is on but the scene has no hidden geometry "
                      "with area to sample"));
    return TransientIntegrator::render(scene, options);
  }

  void sample(const Scene& scene, const Ray& cameraRay, Sampler& sampler, RadianceRecorder& recorder) const override {
    if (depth_.maxDepth == 0) return;
    const NlosSensor* sensor = dynamic_cast<const NlosSensor*>(&scene.sensor());
    NlosPath path;
    if (!scene.rayIntersect(cameraRay, path.si)) return;
    path.opl = path.si.t;
    std::optional<AimedLaser> aimed;
    double shift = 0.0;
    if (sensor) {
      const Point3f target = sensor->laserTarget(path.si.p);
      aimed.emplace(laserOf(scene, *sensor), sensor->laserOrigin(), target);
      if (!sensor->accountsFirstAndLastBounces()) shift = path.si.t + distance(aimed->origin(), target);
    } else {
      aimed.emplace(onlyLaser(scene));  // through a camera: the projector as the scene places it
      if (keepLegs_ && !*keepLegs_) {
        // The laser's leg ends where its axis meets the scene (mitransient's lit point).
        std::optional<Point3f> lit = litPoint(scene, aimed->emitter());
        if (lit) shift = path.si.t + distance(aimed->origin(), *lit);
      }
    }
    Capture capture{*aimed, shift, recorder};
    std::optional<HiddenGeometry> hidden;
    if (hiddenSampling_) hidden.emplace(scene, sensor ? &sensor->relayWall() : nullptr, hiddenIncludesWall_);

    while (true) {
      const BSDF* bsdf = path.si.bsdf();
      if (!bsdf) return;
      if (bsdf->hasDelay()) path.opl += bsdf->sampleDelay(sampler.next1D());
      if (path.opl - shift >= recorder.horizon()) return;
      if (bsdf->hasSmooth()) {
        if (!laserSampling_ || path.segments == 1) nextEventLaser(scene, path, *bsdf, capture);
        if (laserSampling_) laserSample(scene, path, *bsdf, sampler, capture);
      }
      // The shortest contribution a further vertex can make: k + 2 segments
      // (next-event), k + 3 when only laser sampling connects it.
      int shortestNext = path.segments + (laserSampling_ ? 3 : 2);
      if (!depth_.depthAllowed(shortestNext) || (filterDepth_ >= 0 && shortestNext > filterDepth_)) return;
      if (!continuePath(scene, path, *bsdf, hidden ? &*hidden : nullptr, sampler)) return;
      if (path.segments >= depth_.rrDepth) {
        float q = std::min(path.beta.maxValue(), 0.95f);
        if (!(sampler.next1D() < q)) return;
        path.beta = path.beta / q;
      }
    }
  }

  std::string toString() const override {
    return str("TransientNlosPath[", depth_.toString(), ", filter_depth=", filterDepth_,
               ", discard_direct_paths=", discardDirect_, ", nlos_laser_sampling=", laserSampling_,
               ", nlos_hidden_geometry_sampling=", hiddenSampling_, "]");
  }

 private:
  /// Through an ordinary camera: the scene's only emitter is the laser.
  static const Emitter& onlyLaser(const Scene& scene) {
    if (scene.emitters().size() != 1)
      throw Error(str("transient_nlos_path: an NLOS scene has exactly one emitter, the laser; this one has ",
                      scene.emitters().size()));
    return *scene.emitters().front();
  }

  /// Where a projector's axis meets the scene (none for other lights or when it misses).
  static std::optional<Point3f> litPoint(const Scene& scene, const Emitter& emitter) {
    auto* oriented = dynamic_cast<const OrientedPointEmitter*>(&emitter);
    if (!oriented) return std::nullopt;
    Point3f origin(0.0f);
    emitter.deltaPosition(origin);
    SurfaceInteraction lit;
    if (!scene.rayIntersect(Ray(origin, normalize(oriented->toWorld().vector(Vec3f(0, 0, 1)))), lit)) return std::nullopt;
    return lit.p;
  }

  /// The checks of render() for a scene seen through an ordinary camera: one
  /// delta emitter, pointed at the scene (mitransient finds the lit point
  /// along the projector's axis the same way).
  RenderStats renderThroughCamera(const Scene& scene, const RenderOptions& options) const {
    const Emitter& emitter = onlyLaser(scene);
    if (!emitter.isDelta())
      throw Error(str(toString(), ": the laser must be a light at a point (a projector with a small fov), not ",
                      emitter.toString()));
    if (dynamic_cast<const OrientedPointEmitter*>(&emitter) && !litPoint(scene, emitter))
      throw Error(str(toString(), ": the laser ", emitter.toString(), " is not pointing at the scene"));
    if (hiddenSampling_ && HiddenGeometry(scene, nullptr, true).empty())
      throw Error(str(toString(), ": nlos_hidden_geometry_sampling is on but the scene has no geometry with area"));
    return TransientIntegrator::render(scene, options);
  }

  /// The laser: the emitter nested in the capture meter, or the scene's only one.
  static const Emitter& laserOf(const Scene& scene, const NlosSensor& sensor) {
    if (const Emitter* nested = sensor.nestedLaser()) {
      if (!scene.emitters().empty())
        throw Error(str("transient_nlos_path: the capture meter holds its laser and the scene has ",
                        scene.emitters().size(), " more emitter(s); an NLOS scene has exactly one, the laser"));
      return *nested;
    }
    if (scene.emitters().size() != 1)
      throw Error(
          str("transient_nlos_path: an NLOS scene has exactly one emitter, the laser (nested in the "
              "nlos_capture_meter or at top level); this one has ",
              scene.emitters().size()));
    return *scene.emitters().front();
  }

  /// Is a contribution of `segments` segments recorded?
  bool recorded(int segments) const {
    if (!depth_.depthAllowed(segments)) return false;
    if (filterDepth_ >= 0 && segments != filterDepth_) return false;
    return !(discardDirect_ && segments <= 2);
  }

  void deposit(const Capture& c, double opl, const Color3f& value) const {
    if (value.isBlack() || !std::isfinite(value.maxValue())) return;
    c.recorder.addPulsed(opl - c.oplShift, opl - c.oplShift, value, c.laser.emitter().pulse());
  }

  /// Next-event estimation from the path's vertex to the laser.
  void nextEventLaser(const Scene& scene, const NlosPath& path, const BSDF& bsdf, const Capture& c) const {
    if (!recorded(path.segments + 1)) return;
    DirectionSample ds;
    Color3f Le = c.laser.incident(path.si.p, ds);
    if (Le.isBlack() || path.opl + path.eta * ds.dist - c.oplShift >= c.recorder.horizon()) return;
    Color3f f = bsdf.eval(path.si, path.si.toLocal(ds.d));
    if (f.isBlack() || scene.rayTest(path.si.spawnRayTo(ds.p))) return;
    deposit(c, path.opl + path.eta * ds.dist, path.beta * f * Le);
  }

  /// Laser sampling: the laser's own ray picks the lit wall point y; the
  /// path connects to it (header comment for the estimate).
  void laserSample(const Scene& scene, const NlosPath& path, const BSDF& bsdf, Sampler& sampler,
                   const Capture& c) const {
    Point2f uPosition = sampler.next2D(), uDirection = sampler.next2D();
    if (!recorded(path.segments + 2)) return;
    Ray emitted;
    Color3f weight = c.laser.sampleRay(uPosition, uDirection, emitted);
    SurfaceInteraction y;
    if (weight.isBlack() || !scene.rayIntersect(emitted, y) || !y.bsdf()) return;
    Vec3f toY = y.p - path.si.p;
    float dist = length(toY);
    if (!(dist > 0.0f)) return;
    toY = toY / dist;
    double opl = path.opl + double(path.eta) * dist + y.t;
    if (opl - c.oplShift >= c.recorder.horizon()) return;
    Color3f fx = bsdf.eval(path.si, path.si.toLocal(toY));
    if (fx.isBlack()) return;
    // At y light arrives from the laser (y.wi) and leaves toward x: the adjoint evaluation.
    Color3f fy = y.bsdf()->eval(y, y.toLocal(-toY), TransportMode::Importance);
    if (fy.isBlack() || scene.rayTest(path.si.spawnRayTo(y.p))) return;
    deposit(c, opl, path.beta * fx * fy * weight / (dist * dist));
  }

  /// Choose the next direction, trace it and move the path to what it hits.
  bool continuePath(const Scene& scene, NlosPath& path, const BSDF& bsdf, const HiddenGeometry* hidden,
                    Sampler& sampler) const {
    const SurfaceInteraction& si = path.si;
    float uPick = sampler.next1D(), uLobe = sampler.next1D();
    Point2f u = sampler.next2D();
    const bool mixture = hidden && !(bsdf.flags() & BSDFFlags::Delta);
    Vec3f wo;
    Color3f weight;
    float relativeEta = 1.0f;
    if (mixture && (!hiddenRoulette_ || uPick < 0.5f)) {
      if (!hidden->sampleDirection(si, u, wo)) return false;
    } else {
      BSDFSample bs;
      weight = bsdf.sample(si, uLobe, u, bs);
      if (!(bs.pdf > 0.0f) || weight.isBlack()) return false;
      wo = si.toWorld(bs.wo);
      relativeEta = bs.eta;
    }
    if (mixture) {
      // The density of every strategy that could have chosen wo (one-sample mixture).
      Vec3f local = si.toLocal(wo);
      float pdf = hidden->pdf(scene, si, wo);
      if (hiddenRoulette_) pdf = 0.5f * pdf + 0.5f * bsdf.pdf(si, local);
      if (!(pdf > 0.0f)) return false;
      weight = bsdf.eval(si, local) / pdf;
      if (weight.isBlack()) return false;
    }
    SurfaceInteraction next;
    if (!scene.rayIntersect(si.spawnRay(wo), next)) return false;
    path.eta *= relativeEta;
    path.beta *= weight;
    path.opl += double(path.eta) * next.t;
    path.si = next;
    ++path.segments;
    return true;
  }

  PathDepthSettings depth_;
  int filterDepth_ = -1;
  bool discardDirect_ = false;
  bool laserSampling_ = false;
  bool hiddenSampling_ = false;
  bool hiddenRoulette_ = false;
  bool hiddenIncludesWall_ = false;
  std::optional<bool> keepLegs_;  // account_first_and_last_bounces, through a camera
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::TransientNlosPath, Integrator, "transient_nlos_path",
                    "mitransient's non-line-of-sight path tracer: laser and hidden-geometry sampling, exact OPL")
