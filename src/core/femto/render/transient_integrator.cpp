#include <femto/render/transient_integrator.h>

#include <limits>

#include <femto/render/render_loop.h>
#include <femto/render/scene.h>
#include <femto/render/transient_film.h>
#include <femto/render/transient_output.h>
#include <femto/render/transient_tile.h>

namespace femto {
namespace {

/// Steady films: the time of arrival is irrelevant, contributions are summed
/// (no bookkeeping, so the cost is that of a SamplingIntegrator).
class SumRecorder final : public RadianceRecorder {
 public:
  void add(double, const Color3f& value) override { sum += value; }
  void addInterval(double, double, const Color3f& value) override { sum += value; }
  double horizon() const override { return std::numeric_limits<double>::infinity(); }
  const TimeGrid& timeGrid() const override { return grid_; }
  Color3f sum{0.0f};

 private:
  TimeGrid grid_;  // bins == 0: steady
};

RenderStats renderSteady(const TransientIntegrator& integrator, const Scene& scene, const RenderOptions& options) {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  ImageBlock result(film.cropOffset(), film.cropSize(), film.filter());
  auto sampleFn = [&](const Point2f& filmPos, Sampler& sampler) -> Color3f {
    Ray ray;
    Color3f weight = sensor.sampleRay(filmPos, sampler.next2D(), ray);
    if (weight.isBlack()) return Color3f(0.0f);
    SumRecorder recorder;
    integrator.sample(scene, ray, sampler, recorder);
    return weight * recorder.sum;
  };
  RenderStats stats = renderTiles(scene, options, sampleFn, result);
  if (!options.output.empty()) film.develop(result, options.output);
  return stats;
}

RenderStats renderTransient(const TransientIntegrator& integrator, const Scene& scene, const TransientFilm& film,
                            const RenderOptions& options) {
  TransientOutput output(film, options.output);
  TransientRenderContext context{scene, integrator, film.timeDeposit()};
  auto makeTile = [&](const Point2i& offset, const Point2i& size) -> std::unique_ptr<TileAccumulator> {
    return std::make_unique<TransientTile>(offset, size, context);
  };
  auto consume = [&](TileAccumulator& tile) { output.consume(static_cast<TransientTile&>(tile)); };
  RenderStats stats = renderTileStream(scene, options, makeTile, consume);
  output.finish();
  return stats;
}

}  // namespace

RenderStats TransientIntegrator::render(const Scene& scene, const RenderOptions& options) const {
  if (auto* film = dynamic_cast<const TransientFilm*>(&scene.sensor().film()))
    return renderTransient(*this, scene, *film, options);
  return renderSteady(*this, scene, options);
}

}  // namespace femto
