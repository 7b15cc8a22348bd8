#include <femto/view/running_integral.h>

#include <system_error>

#include <femto/base/error.h>
#include <femto/film/volume_scan.h>

namespace femto {

void runningIntegral(const float* in, int bins, float* out, const float* start) {
  double sum[3] = {0, 0, 0};
  if (start)
    for (int c = 0; c < 3; ++c) sum[c] = start[c];
  for (int b = 0; b < bins; ++b)
    for (int c = 0; c < 3; ++c) out[size_t(b) * 3 + c] = float(sum[c] += double(in[size_t(b) * 3 + c]));
}

void accumulateFrames(std::vector<Bitmap>& frames, std::vector<double>& sum) {
  for (Bitmap& frame : frames) {
    sum.resize(frame.data.size(), 0.0);
    for (size_t i = 0; i < frame.data.size(); ++i) frame.data[i] = float(sum[i] += double(frame.data[i]));
  }
}

std::optional<Bitmap> readBeforeImage(const std::filesystem::path& volume, int width, int height) {
  std::filesystem::path file = volume.parent_path() / (volume.stem().string() + "_before.exr");
  if (!std::filesystem::exists(file)) return std::nullopt;
  Bitmap image = readImage(file);
  if (image.width != width || image.height != height || image.channels < 3)
    throw Error(str("\"", file.string(), "\" is ", image.width, "x", image.height, " with ", image.channels,
                    " channels; the volume \"", volume.string(), "\" needs ", width, "x", height, " RGB"));
  return image;
}

void writeRunningIntegral(const NpyVolume& in, const std::filesystem::path& inPath, const std::filesystem::path& out,
                          const Bitmap* before) {
  std::error_code ec;
  if (std::filesystem::equivalent(inPath, out, ec))
    throw Error(str("the running integral would overwrite its input \"", inPath.string(), "\": choose another output"));
  writeAtomically(out, [&](const std::filesystem::path& tmp) {
    NpyVolume result = NpyVolume::create(tmp, in.height(), in.width(), in.bins());
    const size_t pixelFloats = size_t(in.bins()) * 3;
    std::vector<float> sums;
    forEachPixelRun(in, VolumeReadBudgetBytes, [&](int y, int x, int count, const float* data) {
      sums.resize(size_t(count) * pixelFloats);
      for (int p = 0; p < count; ++p)
        runningIntegral(data + size_t(p) * pixelFloats, in.bins(), sums.data() + size_t(p) * pixelFloats,
                        before ? before->pixel(x + p, y) : nullptr);
      result.writePixels(y, x, count, sums.data());
    });
  });
}

}  // namespace femto
