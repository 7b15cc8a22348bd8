#include <transient_beams/boundary_extension.h>

#include <femto/render/medium.h>
#include <femto/render/scene.h>
#include <femto/render/shape.h>
#include <femto/transport/volumetric.h>

namespace femto::beams {

Color3f extensionContinuation(const Medium& medium, float beyond) {
  if (beyond == 0.0f || !medium.isHomogeneous()) return Color3f(1.0f);
  const Color3f sigma = medium.majorant();
  return Color3f(std::exp(-sigma.r * beyond), std::exp(-sigma.g * beyond), std::exp(-sigma.b * beyond));
}

bool sameMediumAcross(const SurfaceInteraction& si, const Vec3f& across, const Medium* medium) {
  const Shape* shape = si.shape;
  if (shape && (shape->interiorMedium() || shape->exteriorMedium())) return mediumAfter(si, across, medium) == medium;
  return isPassThrough(si);
}

}  // namespace femto::beams
