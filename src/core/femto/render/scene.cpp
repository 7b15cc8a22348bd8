#include <femto/render/scene.h>

#include <algorithm>

#include <femto/core/log.h>
#include <femto/render/default_child.h>
#include <femto/render/nlos_sensor.h>
#include <femto/render/detail/embree_accel.h>
#include <femto/render/shape_group.h>
#include <femto/render/transient_integrator.h>
#include <femto/render/bsdf.h>
#include <femto/render/medium.h>

namespace femto {

struct Scene::Accel : detail::EmbreeAccel {
  using detail::EmbreeAccel::EmbreeAccel;
};

/// A scene without light renders black, one without shapes shows only the
/// emitters at infinity: say so rather than write such an image without a word.
void Scene::warnIfEmpty(const Properties& props) const {
  std::string where = props.location().known() ? props.location().toString() + ": " : std::string();
  // A non-line-of-sight capture meter may hold the scene's light, its laser.
  auto* nlos = dynamic_cast<const NlosSensor*>(sensor_.get());
  if (emitters_.empty() && !(nlos && nlos->nestedLaser())) logWarn(where, "the scene has no emitter: the image will be black");
  if (shapes_.empty()) logWarn(where, "the scene has no shape: only emitters at infinity can be seen");
}

Scene::Scene(const Properties& props) {
  for (const auto& obj : props.objectsOfKind(ObjectKind::Shape)) shapes_.push_back(std::static_pointer_cast<Shape>(obj));
  for (const auto& obj : props.objectsOfKind(ObjectKind::Emitter))
    emitters_.push_back(std::static_pointer_cast<Emitter>(obj));
  // Area emitters come from their shapes; one also listed at top level counts once.
  for (const auto& shape : shapes_)
    if (shape->emitterRef() && std::find(emitters_.begin(), emitters_.end(), shape->emitterRef()) == emitters_.end())
      emitters_.push_back(shape->emitterRef());
  // A sensor nested in a shape (an irradiance meter) serves when the scene has no other.
  std::vector<std::shared_ptr<Sensor>> shapeSensors;
  for (const auto& shape : shapes_)
    if (shape->sensorRef()) shapeSensors.push_back(shape->sensorRef());
  if (!shapeSensors.empty()) {
    if (shapeSensors.size() > 1 || props.objectOfKind(ObjectKind::Sensor))
      throw Error(props.location(), str("the scene has ", shapeSensors.size() + (props.objectOfKind(ObjectKind::Sensor) ? 1 : 0),
                                        " sensors (counting those nested in shapes); femto renders exactly one"));
    sensor_ = shapeSensors.front();
  } else {
    sensor_ = nestedOrDefault<Sensor>(props, ObjectKind::Sensor, "perspective");
    if (sensor_->requiresShape())
      throw Error(props.location(), str(sensor_->toString(), " measures on a shape: nest it inside a <shape>"));
  }
  integrator_ = nestedOrDefault<Integrator>(props, ObjectKind::Integrator, "path");
  if (auto* nlos = dynamic_cast<const NlosSensor*>(sensor_.get());
      nlos && nlos->nestedLaser() && !integrator_->tracesNestedLaser())
    throw Error(props.location(),
                str("the capture meter holds its laser, which only transient_nlos_path traces; ",
                    integrator_->toString(), " would render the scene black"));
  // mitransient gives the time filter to the integrator; femto's film owns it.
  if (auto* transient = dynamic_cast<const TransientIntegrator*>(integrator_.get()))
    if (const auto& filter = transient->requestedTimeFilter())
      sensor_->film().useIntegratorTimeFilter(*filter, transient->requestedTimeFilterAt());

  // A shapegroup is only seen through its instances (whose hits report the
  // group's shapes, so those decide what paths may cross and which media
  // they meet). A group its instances reference is not among the scene's
  // shapes, so its shapes are reached through each instance; a group listed
  // on its own is counted directly.
  auto addMedium = [&](const Medium* medium) {
    if (medium) largestMediumEta_ = std::max(largestMediumEta_, medium->eta());
  };
  auto addSurface = [&](const Shape& shape) {
    hasPassThroughShapes_ |= isPassThrough(shape.bsdf());
    hasSmoothSurfaces_ |= shape.bsdf() && shape.bsdf()->hasSmooth();
    addMedium(shape.interiorMedium());
    addMedium(shape.exteriorMedium());
  };
  for (const auto& shape : shapes_) {
    if (auto group = dynamic_cast<const ShapeGroup*>(shape.get())) {
      for (const auto& child : group->shapes()) addSurface(*child);
      continue;
    }
    bbox_.expand(shape->bbox());
    if (auto instance = dynamic_cast<const ShapeInstance*>(shape.get()))
      for (const auto& child : instance->group().shapes()) addSurface(*child);
    else
      addSurface(*shape);
  }
  addMedium(sensor_->medium());
  for (const auto& emitter : emitters_) addMedium(emitter->medium());
  accel_ = std::make_unique<Accel>(shapes_);
  warnIfEmpty(props);

  // Emitters are picked with probability proportional to their sampling weight.
  emitterCdf_.reserve(emitters_.size());
  double sum = 0.0;
  for (const auto& e : emitters_) {
    sum += e->samplingWeight();
    emitterCdf_.push_back(float(sum));
  }
  emitterWeightSum_ = float(sum);
  for (const auto& e : emitters_) {
    e->setScene(*this);
    if (e->isEnvironment()) environment_.push_back(e.get());
  }
}

Scene::~Scene() = default;

bool Scene::rayIntersect(const Ray& ray, SurfaceInteraction& si) const { return accel_->intersect(ray, si); }

bool Scene::rayIntersectPreliminary(const Ray& ray, PreliminaryHit& hit) const {
  return accel_->intersectPreliminary(ray, hit);
}

void Scene::computeInteraction(const Ray& ray, const PreliminaryHit& hit, SurfaceInteraction& si) const {
  accel_->computeInteraction(ray, hit, si);
}

float Scene::rayHitDistance(const Ray& ray) const { return accel_->hitDistance(ray); }

bool Scene::rayTest(const Ray& ray) const { return accel_->occluded(ray); }

float Scene::emitterPickProbability(const Emitter* emitter) const {
  return emitterWeightSum_ > 0.0f ? emitter->samplingWeight() / emitterWeightSum_ : 0.0f;
}

const Emitter* Scene::pickEmitter(float& u) const {
  if (emitterWeightSum_ <= 0.0f) return nullptr;
  // Choose an emitter with u, then rescale the part of u inside its
  // interval back to [0, 1) so it can be reused for the emitter's own sampling.
  float target = u * emitterWeightSum_;
  size_t i = size_t(std::upper_bound(emitterCdf_.begin(), emitterCdf_.end(), target) - emitterCdf_.begin());
  i = std::min(i, emitterCdf_.size() - 1);
  while (i > 0 && emitterCdf_[i] == emitterCdf_[i - 1]) --i;  // never pick a zero-weight emitter
  float start = i == 0 ? 0.0f : emitterCdf_[i - 1];
  float width = emitterCdf_[i] - start;
  u = std::clamp((target - start) / width, 0.0f, 0.99999994f);
  return emitters_[i].get();
}

Color3f Scene::sampleEmitterDirection(const SurfaceInteraction& ref, const Point2f& u, DirectionSample& ds,
                                      bool testVisibility) const {
  ds = DirectionSample();
  float uPick = u.x;
  const Emitter* picked = pickEmitter(uPick);
  if (!picked) return Color3f(0.0f);
  Point2f uReused(uPick, u.y);
  const Emitter& emitter = *picked;
  Color3f value = emitter.sampleDirection(ref.p, uReused, ds);
  if (ds.pdf <= 0.0f || value.isBlack()) return Color3f(0.0f);
  ds.emitter = &emitter;
  float pick = emitterPickProbability(&emitter);
  ds.pdf *= pick;
  value = value / pick;
  if (testVisibility) {
    Ray shadow = std::isfinite(ds.dist) ? ref.spawnRayTo(ds.p) : ref.spawnRay(ds.d);
    if (rayTest(shadow)) return Color3f(0.0f);
  }
  return value;
}

float Scene::pdfEmitterDirection(const Point3f& ref, const DirectionSample& ds, const Emitter* emitter) const {
  return emitter->pdfDirection(ref, ds) * emitterPickProbability(emitter);
}

Color3f Scene::evalEnvironment(const Ray& ray) const {
  Color3f sum(0.0f);
  for (const Emitter* e : environment_) sum += e->evalEnvironment(ray);
  return sum;
}

}  // namespace femto
