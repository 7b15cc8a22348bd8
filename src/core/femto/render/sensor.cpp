#include <femto/render/sensor.h>

#include <femto/render/default_child.h>
#include <femto/render/endpoint_medium.h>
#include <femto/render/medium.h>

namespace femto {
Sensor::Sensor(const Properties& props) {
  toWorld_ = props.getTransform("to_world", Transform());
  film_ = nestedOrDefault<Film>(props, ObjectKind::Film, "hdrfilm");
  sampler_ = nestedOrDefault<Sampler>(props, ObjectKind::Sampler, "independent");
  medium_ = endpointMedium(props);
  // Mitsuba sensors take a shutter interval for motion blur; femto's scenes are static.
  float open = props.getFloat("shutter_open", 0.0f), close = props.getFloat("shutter_close", open);
  if (close < open) props.raise("shutter_close", str("must not be before shutter_open (", open, ")"));
}

void Sensor::useSinglePixelFilmUnlessGiven(const Properties& props) {
  if (props.objectOfKind(ObjectKind::Film)) return;
  Properties box("box");
  box.setLocation(props.location());
  Properties film("hdrfilm");
  film.setLocation(props.location());
  film.setInt("width", 1);
  film.setInt("height", 1);
  film.setObject("rfilter", PluginManager::instance().create(ObjectKind::ReconstructionFilter, box));
  film_ = std::dynamic_pointer_cast<Film>(PluginManager::instance().create(ObjectKind::Film, film));
  if (!film_) throw Error(props.location(), "the hdrfilm plugin did not create a film");
}

void Sensor::setShape(const Shape*) {
  throw Error(str(toString(), " cannot be attached to a shape (only sensors such as irradiancemeter can)"));
}

}  // namespace femto
