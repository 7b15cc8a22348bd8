#pragma once
// The continuous-emission view of a Dirac (pulse) render, without rendering
// again. Light transport is linear and time-invariant, so a source switched on
// at the pulse's time and left on (a step in time) produces at sensor time t
// the integral of the pulse response over [0, t]: the running sum of the
// volume's bins, per pixel and channel (in units of radiance x bin width).
// Energy that arrived before the volume's window (`<stem>_before.exr`) is not
// included: the sum starts at bin 0.
#include <filesystem>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/render/npy_volume.h>

namespace femto {

/// out[b] = sum of in[0..b] for `bins` RGB triples (3 * bins floats), summed
/// in double so that long sequences keep float precision.
void runningIntegral(const float* in, int bins, float* out);

/// Running sum over frames given in bin order: `sum` (3 doubles per pixel,
/// zero at bin 0) is advanced by each frame, which is replaced by the sum so
/// far. Gives bitwise the values of runningIntegral.
void accumulateFrames(std::vector<Bitmap>& frames, std::vector<double>& sum);

/// Write the running integral of `in` as a new volume of the same shape at
/// `out` (atomically; bounded memory). `out` must not be `in`.
void writeRunningIntegral(const NpyVolume& in, const std::filesystem::path& inPath, const std::filesystem::path& out);

}  // namespace femto
