// The CLI's viewing code for NumPy arrays (femto.view): one exposure for a
// whole sequence from a luminance percentile (exposure.h), and frames
// encoded exactly as `femto frames` writes its PNGs (display.h, then
// image_io's sRGB encoding and 8-bit quantisation).
#include <pybind11/numpy.h>

#include <cstring>

#include <femto/base/error.h>
#include <femto/image/image_io.h>
#include <femto/view/display.h>
#include <femto/view/exposure.h>

#include "bindings.h"

namespace py = pybind11;

namespace femto::python {
namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

void requireRgb(const FloatArray& a, const char* what) {
  if (a.ndim() < 1 || a.shape(a.ndim() - 1) != 3)
    throw Error(str(what, " expects an array whose last axis is RGB (3)"));
}

/// The exposure (stops) that maps the `percentile` of all non-black voxels'
/// luminance to white, as `femto frames --percentile`; 0 for a black volume.
float autoExposure(const FloatArray& values, double percentile) {
  requireRgb(values, "auto_exposure");
  if (!(percentile > 0 && percentile <= 100)) throw Error(str("percentile must be in (0, 100], got ", percentile));
  const float* data = values.data();
  const size_t voxels = size_t(values.size()) / 3;
  py::gil_scoped_release release;
  LuminanceHistogram histogram;
  for (size_t i = 0; i < voxels; ++i) histogram.add(luminanceOf(data + 3 * i));
  return exposureForWhite(histogram.percentile(percentile));
}

/// Frames (count x height x width x 3, linear) -> the 8-bit sRGB pixels `femto frames` writes.
py::array_t<uint8_t> displayFrames(const FloatArray& frames, float exposure, bool falseColour) {
  requireRgb(frames, "display_frames");
  if (frames.ndim() != 4) throw Error("display_frames expects count x height x width x 3");
  const int count = int(frames.shape(0)), height = int(frames.shape(1)), width = int(frames.shape(2));
  py::array_t<uint8_t> out({count, height, width, 3});
  const float* in = frames.data();
  uint8_t* bytes = out.mutable_data();
  py::gil_scoped_release release;
  const size_t frameValues = size_t(height) * size_t(width) * 3;
  for (int k = 0; k < count; ++k) {
    Bitmap linear(width, height, 3);
    std::memcpy(linear.data.data(), in + k * frameValues, frameValues * sizeof(float));
    std::vector<uint8_t> encoded = quantize8(encodeSRGB(displayImage(linear, exposure, falseColour), 0.0f));
    std::memcpy(bytes + k * frameValues, encoded.data(), frameValues);
  }
  return out;
}

}  // namespace

void bindView(py::module_& m) {
  m.def("auto_exposure", &autoExposure, py::arg("values"), py::arg("percentile"));
  m.def("display_frames", &displayFrames, py::arg("frames"), py::arg("exposure"), py::arg("false_colour"));
}

}  // namespace femto::python
