// moment: Mitsuba 3's `moment` integrator. Renders with one or more nested
// integrators and records, per pixel, the mean of each one's radiance and
// the mean of its square (the second moment), so the per-pixel variance of
// the samples is m2 - mean^2. Writes one multi-channel OpenEXR image:
//
// | channels                  | value                                    |
// |---------------------------|------------------------------------------|
// | <p>R <p>G <p>B            | mean radiance of nested integrator p     |
// | <p>m2.R <p>m2.G <p>m2.B   | mean squared radiance (per channel)      |
//
// where the prefix <p> is "" for a single nested integrator without id,
// else "<id>." (or "integrator_<k>." for the k-th one without id). Like
// `aov`, it uses the film for size, crop window and filter only (box filter
// recommended: the moments are filter-weighted averages of the samples).
//
// | name         | type       | default | meaning                            |
// |--------------|------------|---------|------------------------------------|
// | (integrator) | integrator | —       | one or more nested integrators     |
//
// A transient film is refused with a message (moments are per pixel, not per
// time bin; rendering it would silently give a steady image only).
#include <functional>

#include <femto/core/plugin.h>
#include <femto/film/channel_output.h>
#include <femto/render/integrator.h>
#include <femto/loop/render_loop.h>
#include <femto/render/scene.h>
#include <femto/time/time_grid.h>
#include <femto/film/transient_film.h>
#include <femto/render/transient_integrator.h>

namespace femto {
namespace {

/// Radiance along a camera ray from a nested integrator of either interface.
using RadianceFunction = std::function<Color3f(const Ray&, const Scene&, Sampler&)>;

RadianceFunction radianceOf(const ObjectRef& integrator) {
  if (auto sampling = std::dynamic_pointer_cast<SamplingIntegrator>(integrator))
    return [sampling](const Ray& ray, const Scene& scene, Sampler& sampler) { return sampling->Li(ray, scene, sampler); };
  if (auto transient = std::dynamic_pointer_cast<TransientIntegrator>(integrator))
    return [transient](const Ray& ray, const Scene& scene, Sampler& sampler) {
      return transient->steadyRadiance(scene, ray, sampler);
    };
  return nullptr;
}

}  // namespace

class MomentIntegrator final : public Integrator {
 public:
  explicit MomentIntegrator(const Properties& props) : location_(props.location()) {
    std::vector<ObjectRef> nested = props.objectsOfKind(ObjectKind::Integrator);
    if (nested.empty()) throw Error(props.location(), "\"moment\" needs at least one nested <integrator>");
    for (size_t k = 0; k < nested.size(); ++k) {
      RadianceFunction radiance = radianceOf(nested[k]);
      if (!radiance)
        throw Error(props.location(), "the nested <integrator>s of \"moment\" must estimate radiance per camera ray");
      integrators_.push_back(radiance);
      std::string prefix = !nested[k]->id().empty() ? nested[k]->id() + "."
                           : nested.size() == 1     ? std::string()
                                                    : str("integrator_", k, ".");
      for (const char* c : {"R", "G", "B"}) channelNames_.push_back(prefix + c);
      for (const char* c : {"R", "G", "B"}) channelNames_.push_back(prefix + "m2." + c);
    }
  }

  RenderStats render(const Scene& scene, const RenderOptions& options) const override {
    const Sensor& sensor = scene.sensor();
    const Film& film = sensor.film();
    // Moments are per pixel, not per time bin: a transient film would end up
    // with a steady image only, so it is refused before any work.
    if (dynamic_cast<const TransientFilm*>(&film))
      throw Error(location_, str("\"moment\" computes per-pixel moments of steady radiance and cannot fill the "
                                 "time-resolved film ", film.toString(), ": render the transient integrator on its own "
                                 "for the volume, or give moment an <film type=\"hdrfilm\"> for the moments"));
    auto sampleFn = [&](const Point2f& filmPos, Sampler& sampler, float* out) {
      Ray ray;
      Color3f weight = sensor.sampleRay(filmPos, sampler.next2D(), ray);
      for (const auto& radiance : integrators_) {
        Color3f L = weight.isBlack() ? Color3f(0.0f) : weight * radiance(ray, scene, sampler);
        for (int c = 0; c < 3; ++c) out[c] = L[c], out[3 + c] = L[c] * L[c];
        out += 6;
      }
    };
    ImageBlock result(film.cropOffset(), film.cropSize(), film.filter(), int(channelNames_.size()));
    RenderStats stats = renderChannelTiles(scene, options, sampleFn, result);
    if (!options.output.empty()) developChannels(result, film, channelNames_, options.output);
    return stats;
  }

  std::string toString() const override { return str("MomentIntegrator[integrators=", integrators_.size(), "]"); }

 private:
  SourceLocation location_;
  std::vector<RadianceFunction> integrators_;
  std::vector<std::string> channelNames_;
};

}  // namespace femto

FEMTO_EXPORT_PLUGIN(femto::MomentIntegrator, Integrator, "moment", "mean and second moment of nested integrators")
