// carom's C++ exceptions as Python ones: a bad scene is carom.SceneError (a ValueError) with the
// message the command line prints after "carom: error: "; a run the physics stops (inelastic
// collapse, an unstable kick or step) is carom.RunError (a RuntimeError) with its diagnostic; a
// stop signal before the run began is KeyboardInterrupt.
#include <Python.h>

#include "events/laws/collapse.hpp"
#include "events/method.hpp"
#include "fluid/kick_scheme.hpp"
#include "scenarios/python/bindings.hpp"
#include "scenarios/scene/input_file.hpp"
#include "scenarios/scene/scene_reader.hpp"
#include "scenarios/scene/settling.hpp"

namespace py = pybind11;

namespace carom::python {

void bind_errors(py::module_& m) {
  static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  scene_error.doc() =
      "A mistake in a scene, a --set value or a command's arguments: the message names the file, "
      "line, key, value and allowed range, as `carom run` prints it. Nothing was run or written.";
  static py::exception<MethodFailure> run_error(m, "RunError", PyExc_RuntimeError);
  run_error.doc() =
      "A run that cannot go on (inelastic collapse, an unstable step, lasting contacts): the "
      "message names the cause and the remedy.";
  py::register_exception_translator([](std::exception_ptr error) {
    if (!error) return;
    try {
      std::rethrow_exception(error);
    } catch (const SceneError& e) {
      scene_error(shorten_long_tokens(e.what()).c_str());
    } catch (const InterruptedBeforeStart& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    } catch (const InelasticCollapse& e) {
      run_error(e.what());
    } catch (const KickUnstable& e) {
      run_error(e.what());
    } catch (const MethodFailure& e) {
      run_error(e.what());
    }
  });
}

}  // namespace carom::python
