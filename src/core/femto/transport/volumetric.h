#pragma once
// Light transport through media, shared by the volumetric integrators
// (transient_path; photon tracers later): which medium a ray is in after
// leaving a surface, index-matched boundaries, and transmittance with optical
// path length along a connection that may cross such boundaries.
#include <femto/math/vector.h>
#include <femto/math/spectrum.h>

namespace femto {

class BSDF;
class Medium;
class Sampler;
class Scene;
struct SurfaceInteraction;

/// The medium a ray leaving `si` in world direction `d` travels through
/// (Mitsuba's convention): the shape's exterior medium on the side its
/// geometric normal points to, its interior on the other; `current` when the
/// shape bounds no medium at all.
const Medium* mediumAfter(const SurfaceInteraction& si, const Vec3f& d, const Medium* current);

/// Does light cross this surface unchanged? True for index-matched boundaries
/// of media: shapes without a BSDF, or with a BSDF that is only Null.
bool isPassThrough(const SurfaceInteraction& si);

/// Index-matched boundaries a path or connection crosses in a row before it
/// is abandoned: guards against rays stuck on coincident or self-intersecting
/// boundaries, where every crossing lands on the same surface again.
inline constexpr int MaxPassThrough = 256;

/// Does the scene hold participating media (a shape's interior or exterior,
/// shapes of groups included, or the sensor's medium)? Surface-only
/// integrators use it to say that they ignore them instead of silently
/// rendering a scene without its fog.
bool sceneHasMedia(const Scene& scene);
/// For surface-only integrators (path, direct) before they render: a warning
/// naming `integrator` when the scene has media, which it will not trace.
void warnIfMediaIgnored(const Scene& scene, const char* integrator);

/// What reaches a point along a connection (next-event estimation).
struct Connection {
  Color3f transmittance{0.0f};  // zero when an opaque or refracting surface blocks it
  double opl = 0.0;             // optical path length of the connection (sum of eta * length)
};

/// Transmittance and OPL from `from.p` (in `medium`) to `target` (or, when
/// `targetDistance` is Infinity, along direction `d` out of the scene), crossing
/// pass-through surfaces and the media they bound. `surfaceEta` is the
/// refractive index where there is no medium (1 outside dielectrics). The
/// OPL of each piece is eta times the distance between its exact end points.
/// Distant connections add no OPL beyond the last surface crossed (light from
/// infinitely far away has no finite path length). Outside media, in a scene
/// without pass-through surfaces, this is one shadow ray (Scene::rayTest).
Connection connect(const Scene& scene, const SurfaceInteraction& from, const Vec3f& d, const Point3f& target,
                   float targetDistance, const Medium* medium, float surfaceEta, Sampler& sampler);

}  // namespace femto
