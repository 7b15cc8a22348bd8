// Test-only sensor: the ray of film position (px, py) starts at (px, py, 0)
// and looks along +z, so test integrators can read the pixel off the ray.
#include <femto/core/plugin.h>
#include <femto/render/sensor.h>

namespace femto::test {

class FilmPositionSensor final : public Sensor {
 public:
  explicit FilmPositionSensor(const Properties& props) : Sensor(props) {}
  Color3f sampleRay(const Point2f& filmPos, const Point2f&, Ray& ray) const override {
    ray = Ray(Point3f(filmPos.x, filmPos.y, 0.0f), Vec3f(0.0f, 0.0f, 1.0f));
    return Color3f(1.0f);
  }
  std::string toString() const override { return "FilmPositionSensor[]"; }
};

}  // namespace femto::test

FEMTO_EXPORT_PLUGIN(femto::test::FilmPositionSensor, Sensor, "test_film_position",
                    "test-only sensor: rays start at their film position")
