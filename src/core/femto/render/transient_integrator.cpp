// Placeholder until the transient film lands (issue 4, worktree
// transient-film replaces this file): TransientIntegrator::render drives
// steady films only, summing each camera sample's contributions.
#include <femto/render/transient_integrator.h>

#include <femto/render/render_loop.h>
#include <femto/render/scene.h>

namespace femto {
namespace {

class SumRecorder final : public RadianceRecorder {
 public:
  void add(double, const Color3f& value) override { sum += value; }
  void addInterval(double, double, const Color3f& value) override { sum += value; }
  double horizon() const override { return Infinity; }
  const TimeGrid& timeGrid() const override { return grid_; }
  Color3f sum{0.0f};

 private:
  TimeGrid grid_;
};

}  // namespace

RenderStats TransientIntegrator::render(const Scene& scene, const RenderOptions& options) const {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  ImageBlock result(film.cropOffset(), film.cropSize(), film.filter());
  auto sampleFn = [&](const Point2f& filmPos, Sampler& sampler) -> Color3f {
    Ray ray;
    Color3f weight = sensor.sampleRay(filmPos, sampler.next2D(), ray);
    if (weight.isBlack()) return Color3f(0.0f);
    SumRecorder recorder;
    sample(scene, ray, sampler, recorder);
    return weight * recorder.sum;
  };
  RenderStats stats = renderTiles(scene, options, sampleFn, result);
  if (!options.output.empty()) film.develop(result, options.output);
  return stats;
}

}  // namespace femto
