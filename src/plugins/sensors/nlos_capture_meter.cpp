// nlos_capture_meter: mitransient's non-line-of-sight capture device. Nested
// in the relay wall (a rectangle, or any mesh with uvs), its film's pixels are
// points on the wall: pixel (i, j) of a width x height film watches the wall
// point at uv ((i + 0.5) / width, (j + 0.5) / height), as mitransient places
// them. Every camera ray starts at sensor_origin and ends at the pixel's wall
// point, with weight 1: the film records the radiance the wall sends toward
// the sensor (time-resolved with a transient_hdr_film).
//
// The laser is the projector nested in this sensor (as mitransient's
// generated scenes write it) or, without one, the scene's only emitter. It
// sits at laser_origin (or where its to_world puts it) and is aimed at the
// wall point laser_lookat_pixel (film pixels, mitransient's convention: uv =
// pixel / film size) or laser_lookat_3d (world); confocal = true aims it, for
// every pixel, at the point that pixel watches. femto renders a confocal scan
// of all width x height points in one render, the capture mitransient's tal
// assembles from one 1x1 render per point; the lookat parameters are then
// read and unused. The integrator (transient_nlos_path) does the aiming.
//
// | name                | type    | default   | meaning                                                  | unit |
// |---------------------|---------|-----------|----------------------------------------------------------|------|
// | sensor_origin       | point   | (0, 0, 0) | where the sensor sits                                    | -    |
// | laser_origin        | point   | the laser's position | where the laser sits                          | -    |
// | laser_lookat_pixel  | point   | -         | the aimed wall point in film pixels (x, y; z must be 0)  | px   |
// | laser_lookat_3d     | point   | (0, 0, 0) | the aimed point in world space (without a lookat pixel)  | -    |
// | confocal            | boolean | false     | aim the laser at each watched point (confocal scan)      | -    |
// | account_first_and_last_bounces | boolean | true | keep the laser-to-wall and wall-to-sensor legs in the OPL | - |
// | (emitter)           | emitter | -         | the laser, usually a projector with a tiny fov           | -    |
// | (film)              | film    | -         | its pixels are the wall points; transient_hdr_film for a capture | - |
#include <cmath>
#include <mutex>
#include <vector>

#include <femto/core/plugin.h>
#include <femto/render/emitter.h>
#include <femto/render/mesh.h>
#include <femto/render/nlos_sensor.h>

namespace femto {

class NlosCaptureMeter final : public NlosSensor {
 public:
  explicit NlosCaptureMeter(const Properties& props) : NlosSensor(props) {
    if (props.has("to_world"))
      props.raise("to_world",
                  "the capture meter takes its wall from the shape it is nested in and sits at "
                  "sensor_origin");
    sensorOrigin_ = props.getPoint("sensor_origin", Point3f(0.0f));
    if (props.has("laser_origin")) laserOrigin_ = props.getPoint("laser_origin");
    confocal_ = props.getBool("confocal", false);
    accountFirstAndLast_ = props.getBool("account_first_and_last_bounces", true);
    laser_ = std::dynamic_pointer_cast<Emitter>(props.objectOfKind(ObjectKind::Emitter));
    // The lookat point: a film pixel (mitransient's generated scenes) or a world point.
    lookat3d_ = props.getPoint("laser_lookat_3d", Point3f(0.0f));
    if (props.has("laser_lookat_pixel")) {
      if (props.has("laser_lookat_3d"))
        props.raise("laser_lookat_3d", "give either laser_lookat_pixel or laser_lookat_3d, not both");
      Point3f pixel = props.getPoint("laser_lookat_pixel");
      const Point2i& size = film().size();
      if (!(pixel.x >= 0.0f && pixel.x <= float(size.x) && pixel.y >= 0.0f && pixel.y <= float(size.y)))
        props.raise("laser_lookat_pixel",
                    str("(", pixel.x, ", ", pixel.y, ") is outside the ", size.x, "x", size.y, " film"));
      if (pixel.z != 0.0f) props.raise("laser_lookat_pixel", "its z must be 0 (it is a film position)");
      lookatUv_ = Point2f(pixel.x / float(size.x), pixel.y / float(size.y));
    }
  }

  void setShape(const Shape* shape) override { wall_ = shape; }
  bool requiresShape() const override { return true; }

  Color3f sampleRay(const Point2f& filmPos, const Point2f&, Ray& ray) const override {
    const Point2i& size = film().size();
    int i = std::clamp(int(std::floor(filmPos.x)), 0, size.x - 1);
    int j = std::clamp(int(std::floor(filmPos.y)), 0, size.y - 1);
    Vec3f d = watchedPoints()[size_t(j) * size_t(size.x) + size_t(i)] - sensorOrigin_;
    float len = length(d);
    if (!(len > 0.0f)) return Color3f(0.0f);
    ray = Ray(sensorOrigin_, d / len);
    return Color3f(1.0f);
  }

  const Shape& relayWall() const override { return *wall_; }
  const Point3f& sensorOrigin() const override { return sensorOrigin_; }
  const Emitter* nestedLaser() const override { return laser_.get(); }
  std::optional<Point3f> laserOrigin() const override { return laserOrigin_; }
  Point3f watchedPoint(int i, int j) const override {
    return watchedPoints()[size_t(j) * size_t(film().size().x) + size_t(i)];
  }

  Point3f laserTarget(const Point3f& watchedPoint) const override {
    if (confocal_) return watchedPoint;
    if (!lookatUv_) return lookat3d_;
    watchedPoints();  // checks the wall once
    return pointAtUv(*lookatUv_);
  }
  bool confocal() const override { return confocal_; }
  bool accountsFirstAndLastBounces() const override { return accountFirstAndLast_; }

  std::string toString() const override {
    return str("NlosCaptureMeter[sensor_origin=", sensorOrigin_, ", confocal=", confocal_ ? "true" : "false",
               ", account_first_and_last_bounces=", accountFirstAndLast_ ? "true" : "false", "]");
  }

 private:
  /// The wall point at texture coordinates `uv`: the triangle of the wall's
  /// mesh whose uv triangle holds it, interpolated barycentrically.
  Point3f pointAtUv(const Point2f& uv) const {
    const TriangleMesh& mesh = wallMesh();
    const auto& idx = mesh.indices();
    const auto& p = mesh.positions();
    const auto& t = mesh.uvs();
    const float eps = 1e-6f;
    for (size_t k = 0; k + 2 < idx.size(); k += 3) {
      Point2f a = t[idx[k]], b = t[idx[k + 1]], c = t[idx[k + 2]];
      float det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
      if (!(std::abs(det) > 1e-12f)) continue;
      float u = ((uv.x - a.x) * (c.y - a.y) - (c.x - a.x) * (uv.y - a.y)) / det;
      float v = ((b.x - a.x) * (uv.y - a.y) - (uv.x - a.x) * (b.y - a.y)) / det;
      if (u >= -eps && v >= -eps && u + v <= 1.0f + eps)
        return p[idx[k]] * (1.0f - u - v) + p[idx[k + 1]] * u + p[idx[k + 2]] * v;
    }
    throw Error(str(toString(), ": no point of the relay wall has uv (", uv.x, ", ", uv.y, ")"));
  }

  const TriangleMesh& wallMesh() const {
    const TriangleMesh* mesh = wall_ ? wall_->asMesh() : nullptr;
    if (!mesh || mesh->uvs().empty())
      throw Error(str(toString(),
                      ": the relay wall must be a rectangle or a mesh with texture coordinates, whose uv "
                      "square the film's pixels divide"));
    return *mesh;
  }

  /// The wall point of every pixel, computed once the wall's geometry exists
  /// (the shape is not built yet when it attaches its sensor).
  const std::vector<Point3f>& watchedPoints() const {
    std::call_once(pointsOnce_, [this] {
      const Point2i& size = film().size();
      std::vector<Point3f> points(size_t(size.x) * size_t(size.y));
      for (int j = 0; j < size.y; ++j)
        for (int i = 0; i < size.x; ++i)
          points[size_t(j) * size_t(size.x) + size_t(i)] =
              pointAtUv(Point2f((float(i) + 0.5f) / float(size.x), (float(j) + 0.5f) / float(size.y)));
      points_ = std::move(points);
    });
    return points_;
  }

  const Shape* wall_ = nullptr;
  Point3f sensorOrigin_;
  std::optional<Point3f> laserOrigin_;
  std::optional<Point2f> lookatUv_;
  Point3f lookat3d_;
  bool confocal_ = false;
  bool accountFirstAndLast_ = true;
  std::shared_ptr<Emitter> laser_;
  mutable std::once_flag pointsOnce_;
  mutable std::vector<Point3f> points_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::NlosCaptureMeter, Sensor, "nlos_capture_meter",
                    "mitransient's non-line-of-sight capture: film pixels are points on the relay wall it is nested in")
