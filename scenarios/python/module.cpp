// The compiled part of the Python package `carom` (scenarios/python/README.md). The package's
// __init__.py imports it and adds the pure-Python reader of run files (_output.py).
#include "carom/version.hpp"
#include "scenarios/python/bindings.hpp"

PYBIND11_MODULE(_carom, m) {
  m.doc() = "carom's scenes, runs and simulations (the compiled part of the carom package)";
  m.attr("version") = carom::kVersion;
  m.attr("executable") = CAROM_EXECUTABLE;
  carom::python::bind_errors(m);
  carom::python::bind_scene(m);
  carom::python::bind_simulation(m);
  carom::python::bind_runs(m);
}
