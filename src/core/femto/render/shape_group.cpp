#include <femto/render/shape_group.h>

#include <femto/render/emitter.h>

namespace femto {

ShapeGroup::ShapeGroup(const Properties& props) : Shape(props) {
  for (const auto& obj : props.objectsOfKind(ObjectKind::Shape)) {
    auto shape = std::static_pointer_cast<Shape>(obj);
    if (dynamic_cast<const ShapeGroup*>(shape.get()) || dynamic_cast<const ShapeInstance*>(shape.get()))
      throw Error(props.location(), "a shapegroup cannot contain another shapegroup or an instance "
                                    "(only one level of instancing is supported)");
    if (shape->emitter())
      throw Error(props.location(), str("a shapegroup cannot contain area emitters (", shape->toString(),
                                        " has one): instanced shapes are not sampled as lights"));
    bbox_.expand(shape->bbox());
    shapes_.push_back(std::move(shape));
  }
  if (shapes_.empty()) throw Error(props.location(), "the shapegroup contains no shapes");
  if (emitter()) throw Error(props.location(), "a shapegroup cannot be an area emitter");
}

float ShapeGroup::surfaceArea() const {
  float sum = 0.0f;
  for (const auto& s : shapes_) sum += s->surfaceArea();
  return sum;
}

PositionSample ShapeGroup::samplePosition(const Point2f&) const {
  throw Error(str(toString(), ": a shapegroup cannot be sampled"));
}

void ShapeGroup::computeInteraction(const Ray&, float, uint32_t, const Point2f&, SurfaceInteraction&) const {
  throw Error(str(toString(), ": a shapegroup is only intersected through its instances"));
}

std::string ShapeGroup::toString() const {
  return str("ShapeGroup[id=\"", id(), "\", shapes=", shapes_.size(), "]");
}

ShapeInstance::ShapeInstance(const Properties& props) : Shape(props) {
  ObjectRef ref = props.objectOfKind(ObjectKind::Shape);
  group_ = std::dynamic_pointer_cast<ShapeGroup>(ref);
  if (!group_)
    throw Error(props.location(), ref ? str("an instance must reference a shapegroup, not ", ref->toString())
                                      : std::string("an instance needs a <ref id=\"...\"/> to a shapegroup"));
  toWorld_ = props.getTransform("to_world", Transform());
  toLocal_ = toWorld_.inverse();
  if (emitter()) throw Error(props.location(), "an instance cannot carry an area emitter");
}

float ShapeInstance::surfaceArea() const { throw Error(str(toString(), ": instances have no surface area")); }

PositionSample ShapeInstance::samplePosition(const Point2f&) const {
  throw Error(str(toString(), ": an instance cannot be sampled"));
}

void ShapeInstance::computeInteraction(const Ray&, float, uint32_t, const Point2f&, SurfaceInteraction&) const {
  throw Error(str(toString(), ": instances are resolved by the scene's acceleration structure"));
}

void ShapeInstance::interactionToWorld(SurfaceInteraction& si) const {
  si.p = toWorld_.point(si.p);
  // Normals transform with the inverse transpose; the shading frame is rebuilt
  // orthonormal around the transformed shading normal, its tangent following
  // the transformed s (Gram-Schmidt) so anisotropic BSDFs keep their orientation.
  si.n = normalize(toWorld_.normal(si.n));
  Normal3f ns = normalize(toWorld_.normal(si.sh.n));
  Vec3f s = toWorld_.vector(si.sh.s);
  s = s - ns * dot(ns, s);
  float len = length(s);
  si.sh = len > 1e-12f ? Frame(s / len, cross(ns, s / len), ns) : Frame(ns);
}

std::string ShapeInstance::toString() const {
  return str("ShapeInstance[group=\"", group_->id(), "\", to_world=", toWorld_.matrix(), "]");
}

}  // namespace femto
