#include <transient_beams/boundary_extension.h>

#include <femto/render/scene.h>
#include <femto/render/shape.h>
#include <femto/transport/volumetric.h>

namespace femto::beams {

bool sameMediumAcross(const SurfaceInteraction& si, const Vec3f& across, const Medium* medium) {
  const Shape* shape = si.shape;
  if (shape && (shape->interiorMedium() || shape->exteriorMedium())) return mediumAfter(si, across, medium) == medium;
  return isPassThrough(si);
}

}  // namespace femto::beams
