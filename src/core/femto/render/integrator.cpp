#include <femto/render/integrator.h>

#include <femto/render/render_loop.h>
#include <femto/render/scene.h>

namespace femto {

RenderStats SamplingIntegrator::render(const Scene& scene, const RenderOptions& options) const {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  ImageBlock result(film.cropOffset(), film.cropSize(), film.filter());
  auto sampleFn = [&](const Point2f& filmPos, Sampler& sampler) -> Color3f {
    Ray ray;
    Color3f weight = sensor.sampleRay(filmPos, sampler.next2D(), ray);
    if (weight.isBlack()) return Color3f(0.0f);
    return weight * Li(ray, scene, sampler);
  };
  RenderStats stats = renderTiles(scene, options, sampleFn, result);
  if (!options.output.empty()) film.develop(result, options.output);
  return stats;
}

}  // namespace femto
