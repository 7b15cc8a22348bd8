#pragma once
// The continuous-emission view of a Dirac (pulse) render, without rendering
// again. Light transport is linear and time-invariant, so a source switched on
// at the pulse's time and left on (a step in time) produces at sensor time t
// the integral of the pulse response over [0, t]: the running sum of the
// volume's bins, per pixel and channel (in units of radiance x bin width),
// starting from the light that arrived before the volume's window
// (`<stem>_before.exr`, when there is one): a source left on keeps lighting
// every later frame with it. This is what a render with a continuous pulse
// puts in its bins (a step arriving before the window fills every bin).
#include <filesystem>
#include <optional>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/film/npy_volume.h>

namespace femto {

/// out[b] = start + sum of in[0..b] for `bins` RGB triples (3 * bins floats),
/// summed in double so that long sequences keep float precision; `start` is
/// an RGB triple or nullptr (zero).
void runningIntegral(const float* in, int bins, float* out, const float* start = nullptr);

/// The image of light that arrived before the window of the volume at
/// `volume` (`<stem>_before.exr` beside it), or nothing when there is none.
/// It must be RGB(A) of the volume's size (an error naming it otherwise).
std::optional<Bitmap> readBeforeImage(const std::filesystem::path& volume, int width, int height);

/// Running sum over frames given in bin order: `sum` (3 doubles per pixel;
/// before bin 0 empty, i.e. zero, or set to the before image's values) is
/// advanced by each frame, which is replaced by the sum so far. Gives bitwise
/// the values of runningIntegral.
void accumulateFrames(std::vector<Bitmap>& frames, std::vector<double>& sum);

/// Write the running integral of `in` (from `before`, when given) as a new
/// volume of the same shape at `out` (atomically; bounded memory). `out` must
/// not be `in`.
void writeRunningIntegral(const NpyVolume& in, const std::filesystem::path& inPath, const std::filesystem::path& out,
                          const Bitmap* before = nullptr);

}  // namespace femto
