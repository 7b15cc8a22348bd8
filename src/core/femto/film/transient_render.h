#pragma once
// Rendering with a transient integrator: the passes over the whole film and
// where their contributions go (a transient film's streamed volume, or a
// steady image). TransientIntegrator::render is the one-pass case; transient
// photon beams render several.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <femto/render/integrator.h>
#include <femto/render/transient_integrator.h>

namespace femto {

class Film;
class Scene;

/// Progressive transient rendering (photon beams): before pass `pass`, called
/// serially with the film's horizon (allowing for the scene's emitter pulses:
/// pulsedHorizon in transient_tile.h; Infinity for steady films), returns the
/// integrator that renders that pass -- e.g. one holding the pass's photon
/// maps, released when the pass ends so memory stays that of one pass.
using TransientPassFunction = std::function<std::shared_ptr<const TransientIntegrator>(int pass, double horizon)>;

/// An NLOS capture's geometry beside its output `volume` (nothing for other
/// sensors): writes <stem>_wall.npy (the watched wall point of every pixel,
/// height x width x 3) and returns the sidecar fields naming it and the
/// laser and sensor (nlos_confocal, nlos_legs, nlos_sensor_origin,
/// nlos_laser_origin, nlos_laser_target, nlos_wall_points), so a
/// reconstruction needs only the capture (tools/nlos/reconstruct.py).
std::vector<std::pair<std::string, std::string>> describeNlosCapture(const Scene& scene, const Film& film,
                                                                   const std::filesystem::path& volume);

/// `passes` independent renders of the whole film (pass seeds: passSeed in
/// render_loop.h) averaged with equal weights. Transient films fold each
/// finished tile into the streamed volume as a running mean (after a cancel
/// the output is the mean of the passes done); steady films merge the passes'
/// samples. TransientIntegrator::render is the one-pass case.
RenderStats renderTransientPasses(const Scene& scene, const RenderOptions& options, int passes,
                                  const TransientPassFunction& passIntegrator);

}  // namespace femto
