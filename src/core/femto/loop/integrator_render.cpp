// The steady render driver: a sampling integrator over the film's tiles.
#include <femto/render/integrator.h>

#include <femto/loop/render_loop.h>
#include <femto/render/scene.h>

namespace femto {

RenderStats SamplingIntegrator::render(const Scene& scene, const RenderOptions& options) const {
  const Film& film = scene.sensor().film();
  // Checked before rendering rather than when developing: a steady estimator
  // has no times of arrival to fill a transient film with.
  if (film.timeResolved())
    throw Error(str("integrator ", toString(), " is not transient: a transient film needs a transient integrator (e.g. "
                    "transient_path), or use hdrfilm for a steady image"));
  return renderSteadyImage(scene, options, [&](const Ray& ray, Sampler& sampler) { return Li(ray, scene, sampler); });
}

}  // namespace femto
