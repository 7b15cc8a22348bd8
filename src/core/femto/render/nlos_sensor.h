#pragma once
// Non-line-of-sight (NLOS) capture set-ups (mitransient's nlos_capture_meter):
// a sensor nested in a relay wall whose film pixels are points on the wall, a
// sensor at `sensorOrigin()` watching them, and a laser at `laserOrigin()`
// aimed at one wall point (or, confocally, at the point each pixel watches).
// What NLOS integrators need of the set-up, apart from the plugin that reads
// it (Royo et al., "Non-line-of-sight transient rendering", C&G 2022).
#include <optional>

#include <femto/math/vector.h>
#include <femto/render/sensor.h>

namespace femto {

class Emitter;

class NlosSensor : public Sensor {
 public:
  using Sensor::Sensor;
  ~NlosSensor() override;

  /// The relay wall the sensor is nested in.
  virtual const Shape& relayWall() const = 0;
  /// Where the sensor sits: every camera ray starts there.
  virtual const Point3f& sensorOrigin() const = 0;
  /// The laser nested in the sensor (mitransient's generated scenes), or
  /// null: then the laser is the scene's only emitter.
  virtual const Emitter* nestedLaser() const = 0;
  /// Where the laser sits, when the sensor says (laser_origin); otherwise the
  /// laser's own position.
  virtual std::optional<Point3f> laserOrigin() const = 0;
  /// The wall point the laser is aimed at while the sensor watches
  /// `watchedPoint`: that point itself for a confocal capture, the fixed
  /// laser_lookat point otherwise.
  virtual Point3f laserTarget(const Point3f& watchedPoint) const = 0;
  virtual bool confocal() const = 0;
  /// False: the OPL of the sensor-to-wall and laser-to-wall legs is removed
  /// from every contribution (mitransient's account_first_and_last_bounces).
  virtual bool accountsFirstAndLastBounces() const = 0;
  /// The wall point film pixel (i, j) watches.
  virtual Point3f watchedPoint(int i, int j) const = 0;
};

}  // namespace femto
