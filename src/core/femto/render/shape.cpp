#include <femto/render/shape.h>

#include <femto/core/plugin.h>
#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>
#include <femto/render/medium.h>
#include <femto/render/sensor.h>

namespace femto {
namespace {

std::shared_ptr<Medium> mediumRef(const Properties& props, const std::string& name) {
  if (!props.has(name)) return nullptr;
  auto medium = std::dynamic_pointer_cast<Medium>(props.getObject(name));
  if (!medium) props.raise(name, "expected a <medium>");
  return medium;
}

}  // namespace

Shape::Shape(const Properties& props) {
  bsdf_ = props.object<BSDF>(ObjectKind::BSDF);
  emitter_ = props.object<Emitter>(ObjectKind::Emitter);
  interior_ = mediumRef(props, "interior");
  exterior_ = mediumRef(props, "exterior");
  // Mitsuba gives a shape without a BSDF a grey diffuse one, except for
  // shapes that only delimit a medium (their surface is index-matched).
  if (!bsdf_ && !interior_ && !exterior_) {
    Properties diffuse("diffuse");
    diffuse.setFloat("reflectance", 0.5);
    diffuse.setLocation(props.location());
    bsdf_ = std::dynamic_pointer_cast<BSDF>(PluginManager::instance().create(ObjectKind::BSDF, diffuse));
  }
  // The derived constructor has not built the geometry yet: emitters must only
  // remember the shape here and query it later.
  if (emitter_) emitter_->setShape(this);
  sensor_ = props.object<Sensor>(ObjectKind::Sensor);
  if (sensor_) {
    try {
      sensor_->setShape(this);
    } catch (const Error& e) {
      throw Error(props.location(), e.what());
    }
  }
}

Shape::~Shape() = default;

bool Shape::intersect(const Ray&, float&, Point2f&) const {
  throw Error(str(toString(), " is not a triangle mesh and does not implement intersect()"));
}

}  // namespace femto
