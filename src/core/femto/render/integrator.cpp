#include <femto/render/integrator.h>

#include <femto/render/render_loop.h>
#include <femto/render/scene.h>
#include <femto/render/transient_film.h>

namespace femto {

RenderStats SamplingIntegrator::render(const Scene& scene, const RenderOptions& options) const {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  // Checked before rendering rather than when developing: a steady estimator
  // has no times of arrival to fill a transient film with.
  if (dynamic_cast<const TransientFilm*>(&film))
    throw Error(str("integrator ", toString(), " is not transient: a transient film needs a transient integrator (e.g. "
                    "transient_path), or use hdrfilm for a steady image"));
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
