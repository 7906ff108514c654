#pragma once
/// The parts of the `_carom` extension, one per concept, registered by module.cpp.
#include <pybind11/pybind11.h>

namespace carom::python {

/// carom.SceneError, carom.RunError and the translation of carom's C++ exceptions into them.
void bind_errors(pybind11::module_& m);
/// Scene: from_file, from_text, set, check, to_toml.
void bind_scene(pybind11::module_& m);
/// Simulation: stepping in process and the state as numpy arrays.
void bind_simulation(pybind11::module_& m);
/// run, resume, sweep, chart: the commands' own machinery.
void bind_runs(pybind11::module_& m);

}  // namespace carom::python
