#pragma once
// Emission a transient camera path finds (transient_path, and transient_beams'
// camera side), recorded at the path's OPL with the pulse of the emitter it
// came from (Emitter::pulse(): the film convolves exactly). Light from an
// emitter at infinity has no finite path: its emission is recorded at the OPL
// of the path's last vertex.
#include <femto/math/spectrum.h>
#include <femto/math/vector.h>

namespace femto {

class RadianceRecorder;
class Scene;
struct Ray;
struct ScatterOrigin;
struct SurfaceInteraction;

/// A path that left the scene along `ray` with `throughput` at OPL `opl`:
/// records each environment emitter's radiance (environmentFound,
/// MIS-weighted against emitter sampling from `from`) with its pulse.
void recordEnvironmentEmission(const Scene& scene, const Ray& ray, const ScatterOrigin& from, double opl,
                               const Color3f& throughput, RadianceRecorder& recorder);

/// A path that reached surface `si` along direction `d`, `distance` from
/// `from.p`, with `throughput` at OPL `opl`: records its emission
/// (emissionFound, MIS-weighted against emitter sampling from `from`) with
/// the emitter's pulse. Nothing when `si` is not on an emitter.
void recordSurfaceEmission(const Scene& scene, const SurfaceInteraction& si, const Vec3f& d, float distance,
                           const ScatterOrigin& from, double opl, const Color3f& throughput,
                           RadianceRecorder& recorder);

}  // namespace femto
