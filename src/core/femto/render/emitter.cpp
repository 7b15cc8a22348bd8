#include <femto/render/emitter.h>

#include <cmath>

#include <femto/render/endpoint_medium.h>
#include <femto/render/medium.h>

namespace femto {

Emitter::Emitter(const Properties& props) {
  samplingWeight_ = props.getFloat("sampling_weight", 1.0f, Range::nonNegative());
  pulse_ = EmissionPulse::fromProperties(props);
  medium_ = endpointMedium(props);
}

Color3f Emitter::eval(const SurfaceInteraction&, const Vec3f&) const { return Color3f(0.0f); }

Color3f Emitter::evalEnvironment(const Ray&) const { return Color3f(0.0f); }

Color3f Emitter::sampleRay(const Point2f&, const Point2f&, Ray&) const {
  throw Error(str("sampling emitted rays is not supported by ", toString()));
}

Color3f Emitter::power() const { throw Error(str("computing the emitted power is not supported by ", toString())); }

void Emitter::setShape(const Shape*) {
  throw Error(str(toString(), " cannot be attached to a shape (only area emitters can)"));
}

void Emitter::setScene(const Scene&) {}

}  // namespace femto
