#pragma once
// The parts of the `femto._femto` extension module, one file each; module.cpp
// puts them together. The Python package around it (femto/) is the public face.
#include <pybind11/pybind11.h>

namespace femto::python {

/// femto.SceneError and the translation of femto::Error into it.
void bindSceneError(pybind11::module_& m);
/// Scene loading, the scene's description, the plugin list.
void bindScene(pybind11::module_& m);
/// The render driver: GIL released, Ctrl-C and progress handled on the Python thread.
void bindRender(pybind11::module_& m);
/// Images in and out (EXR), and `femto compare`'s metrics.
void bindImages(pybind11::module_& m);
/// Exposure and frame encoding of the CLI's viewing tools (femto.view).
void bindView(pybind11::module_& m);

}  // namespace femto::python
