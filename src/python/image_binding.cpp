// Images between femto and NumPy (float32, height x width x channels), and
// `femto compare`'s metrics (femto_view's compareFiles, the code the CLI
// runs) as the dict of its JSON report (docs/compare.md).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstring>

#include <femto/analysis/compare_files.h>
#include <femto/base/error.h>
#include <femto/image/image_io.h>

#include "bindings.h"

namespace py = pybind11;

namespace femto::python {
namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

FloatArray readImageArray(const std::filesystem::path& path) {
  Bitmap image;
  {
    py::gil_scoped_release release;
    image = readImage(path);
  }
  FloatArray array({image.height, image.width, image.channels});
  std::memcpy(array.mutable_data(), image.data.data(), image.data.size() * sizeof(float));
  return array;
}

void writeExrArray(const std::filesystem::path& path, const FloatArray& array) {
  if (array.ndim() != 3 || (array.shape(2) != 1 && array.shape(2) != 3 && array.shape(2) != 4))
    throw Error("write_exr expects a height x width x channels array with 1, 3 or 4 channels");
  Bitmap image(int(array.shape(1)), int(array.shape(0)), int(array.shape(2)));
  std::memcpy(image.data.data(), array.data(), image.data.size() * sizeof(float));
  py::gil_scoped_release release;
  writeEXR(path, image);
}

py::dict metricsDict(const ErrorMetrics& m, bool withPsnr) {
  py::dict d;
  d["mse"] = m.mse;
  d["relmse"] = m.relMse;
  d["mae"] = m.mae;
  d["max_error"] = m.maxError;
  if (withPsnr) d["psnr"] = psnr(m.mse, m.referencePeak);
  d["reference_peak"] = m.referencePeak;
  d["count"] = m.count;
  return d;
}

/// The fields and names of `femto compare --json` (tools/femto/compare_report.cpp).
py::dict comparisonDict(const Comparison& c) {
  py::dict d;
  d["reference"] = c.reference.string();
  d["test"] = c.test.string();
  d["kind"] = c.transient ? "volume" : "image";
  d["width"] = c.width;
  d["height"] = c.height;
  d["channels"] = c.channels;
  d["pixels"] = c.pixels;
  d["epsilon"] = c.epsilon;
  d["metrics"] = metricsDict(c.metrics, !c.transient);
  if (!c.transient) return d;
  d["bins"] = c.bins;
  d["bin_range"] = py::make_tuple(c.binBegin, c.binEnd);
  if (c.grid) {
    d["start_opl"] = c.grid->start;
    d["bin_width_opl"] = c.grid->binWidth;
  }
  d["time_integral"] = metricsDict(c.integral, false);
  py::dict perBin;
  py::list bin, mse, relmse, mae, maxError;
  for (size_t i = 0; i < c.perBin.size(); ++i) {
    bin.append(c.binBegin + int(i));
    mse.append(c.perBin[i].mse);
    relmse.append(c.perBin[i].relMse);
    mae.append(c.perBin[i].mae);
    maxError.append(c.perBin[i].maxError);
  }
  perBin["bin"] = bin, perBin["mse"] = mse, perBin["relmse"] = relmse, perBin["mae"] = mae;
  perBin["max_error"] = maxError;
  d["per_bin"] = perBin;
  return d;
}

py::dict compare(const std::filesystem::path& reference, const std::filesystem::path& test, double epsilon,
                 std::optional<std::tuple<int, int, int, int>> crop, const std::filesystem::path& mask,
                 std::optional<std::pair<std::optional<int>, std::optional<int>>> bins) {
  CompareSettings settings;
  settings.epsilon = epsilon;
  if (crop) settings.crop = PixelRect{std::get<0>(*crop), std::get<1>(*crop), std::get<2>(*crop), std::get<3>(*crop)};
  settings.mask = mask;
  if (bins) {
    settings.bins = BinRange{bins->first, bins->second};
    settings.binsGiven = true;
  }
  Comparison c;
  {
    py::gil_scoped_release release;  // volumes are streamed from disk
    c = compareFiles(reference, test, settings);
  }
  return comparisonDict(c);
}

}  // namespace

void bindImages(py::module_& m) {
  m.def("read_image", &readImageArray, py::arg("path"), "An image file as float32 height x width x channels");
  m.def("write_exr", &writeExrArray, py::arg("path"), py::arg("image"), "float32 height x width x 1|3|4 -> OpenEXR");
  m.def("compare_files", &compare, py::arg("reference"), py::arg("test"), py::arg("epsilon"), py::arg("crop"),
        py::arg("mask"), py::arg("bins"), "`femto compare REF TEST --json` as a dict");
  m.attr("default_relmse_epsilon") = DefaultRelMseEpsilon;
}

}  // namespace femto::python
