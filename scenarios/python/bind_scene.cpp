// carom.Scene: a scene file read, changed key by key as with `--set`, checked as by `carom
// check`, and written back as TOML.
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "scenarios/cli/check.hpp"
#include "scenarios/python/bindings.hpp"
#include "scenarios/python/scene_source.hpp"
#include "scenarios/python/signal_guard.hpp"

namespace py = pybind11;

namespace carom::python {

namespace {

/// A Python value as the TOML text of a `--set` value: bool, int, float (Python's shortest
/// round-trip repr, so 0.8 stays "0.8"), str (a quoted TOML string), and lists, tuples and
/// dicts of those (arrays and inline tables). numpy scalars count as the numbers they hold.
std::string toml_value(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  if (py::isinstance<py::float_>(value)) return py::repr(value).cast<std::string>();
  if (py::isinstance<py::str>(value)) {
    // A TOML basic string: JSON's escapes are TOML's.
    return py::module_::import("json").attr("dumps")(value).cast<std::string>();
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::string text = "[";
    for (const py::handle item : value) text += (text.size() > 1 ? ", " : "") + toml_value(item);
    return text + "]";
  }
  if (py::isinstance<py::dict>(value)) {
    std::string text = "{";
    for (const auto& [key, item] : value.cast<py::dict>()) {
      std::string name = py::str(key).cast<std::string>();
      const bool bare = !name.empty() && name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                                 "0123456789_-") == std::string::npos;
      if (!bare) name = toml_value(py::str(name));  // a quoted key
      text += (text.size() > 1 ? ", " : " ") + name + " = " + toml_value(item);
    }
    return text + " }";
  }
  if (py::hasattr(value, "__index__")) return py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  if (py::hasattr(value, "__float__"))
    return py::repr(py::float_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  throw py::type_error("Scene.set: a value must be a bool, number, string, or a list or dict of them, not " +
                       py::str(py::type::of(value)).cast<std::string>());
}

/// summary-style number: NaN (not estimated) as None.
py::object number(double value) { return std::isnan(value) ? py::none() : py::object(py::float_(value)); }

py::dict numbers_dict(const SceneNumbers& n) {
  py::dict d;
  py::list species;
  for (const SpeciesNumbers& s : n.species) {
    py::dict one;
    one["name"] = s.name;
    one["mass_share"] = s.mass_share;
    one["relaxation_time"] = number(s.relaxation_time);
    one["stokes"] = number(s.stokes);
    one["minimum_fluidization"] = number(s.minimum_fluidization);
    species.append(one);
  }
  d["species"] = species;
  d["solid_fraction"] = n.solid_fraction;
  d["solid_fraction_seen"] = n.solid_fraction_seen;
  d["packing_source"] = n.packing_source;
  d["speed"] = number(n.speed);
  d["speed_source"] = n.speed_source;
  d["mean_free_time"] = number(n.mean_free_time);
  d["contact_time"] = number(n.contact_time);
  d["contact_source"] = n.contact_source;
  d["young_modulus"] = number(n.young_modulus);
  d["peak_overlap"] = number(n.peak_overlap);
  d["lasting_share"] = n.lasting_share;
  d["lasting_reason"] = n.lasting_reason;
  d["inlet_velocity"] = n.inlet_velocity;
  d["mass_loading"] = number(n.mass_loading);
  d["cell_ratio"] = number(n.cell_ratio);
  d["tube_ratio"] = number(n.tube_ratio);
  d["tube"] = n.tube;
  d["gas_dimensions_needed"] = n.gas_dimensions_needed;
  d["gas_dimensions"] = n.gas_dimensions;
  d["step_ratio"] = number(n.step_ratio);
  return d;
}

}  // namespace

void bind_scene(py::module_& m) {
  py::class_<CheckReport>(m, "Check",
                          "What `carom check` finds: `text` as it prints it, the estimates (`numbers`, "
                          "SI units, None where not estimated) and the recommendations (`advice`, the "
                          "method first; `method` is its choice).")
      .def_readonly("text", &CheckReport::text)
      .def_property_readonly("numbers", [](const CheckReport& r) { return numbers_dict(r.numbers); })
      .def_property_readonly("advice",
                             [](const CheckReport& r) {
                               py::list advice;
                               for (const Advice& a : r.advice)
                                 advice.append(py::dict(py::arg("topic") = a.topic, py::arg("choice") = a.choice,
                                                        py::arg("reason") = a.reason, py::arg("scene") = a.scene,
                                                        py::arg("differs") = a.differs));
                               return advice;
                             })
      .def_property_readonly("method",
                             [](const CheckReport& r) { return std::string(method_name(recommended_method(r.advice))); })
      .def("__str__", [](const CheckReport& r) { return r.text; })
      .def("__repr__", [](const CheckReport& r) {
        return "<carom.Check: recommends " + std::string(method_name(recommended_method(r.advice))) + ">";
      });

  py::class_<SceneSource>(m, "Scene",
                          "A scene: a TOML file (scenarios/scenes/SCENES.md) and the changes made to it "
                          "with set(), each validated at once as `carom run --set` validates it.")
      .def_static("from_file", &SceneSource::from_file, py::arg("path"), "Reads and validates a scene file.")
      .def_static("from_text", &SceneSource::from_text, py::arg("text"), py::arg("file") = "scene.toml",
                  "Validates a scene given as text; `file` names it in messages, and relative paths in "
                  "the scene are taken from its folder.")
      .def(
          "set",
          [](SceneSource& source, const std::string& key, const py::handle& value) -> SceneSource& {
            source.set(key + "=" + toml_value(value));
            return source;
          },
          py::arg("key"), py::arg("value"),
          "Changes one key (\"gas.boundaries.z_low.velocity\", \"species.fines.diameter\") as "
          "`--set key=value` does, and validates the scene again: a refused value raises SceneError "
          "with the command line's message and leaves the scene as it was. Returns the scene.",
          py::return_value_policy::reference_internal)
      .def(
          "check",
          [](const SceneSource& source, bool settle) {
            const py::gil_scoped_release unlocked;
            const SignalGuard signals;
            return check_report(source.scene(), settle);
          },
          py::arg("settle") = false,
          "What `carom check` prints, as data (places the particles; runs the settling only with "
          "settle=True).")
      .def("to_toml", [](const SceneSource& source) { return source.scene().text; },
           "The scene text as run: the file's text, or with changes the table written out again "
           "after a comment that lists them.")
      .def_property_readonly("file", [](const SceneSource& s) { return s.scene().file; })
      .def_property_readonly("name", [](const SceneSource& s) { return s.scene().name; })
      .def_property_readonly("description", [](const SceneSource& s) { return s.scene().description; })
      .def_property_readonly("method", [](const SceneSource& s) { return std::string(method_name(s.scene().method.kind)); })
      .def_property_readonly("end_time", [](const SceneSource& s) { return s.scene().end_time; }, "s")
      .def_property_readonly("seed", [](const SceneSource& s) { return s.scene().seed; })
      .def_property_readonly("species", [](const SceneSource& s) {
        std::vector<std::string> names;
        for (const Species& species : s.scene().system.species) names.push_back(species.name);
        return names;
      })
      .def_property_readonly("changes", &SceneSource::assignments, "The set() changes so far, as KEY=VALUE.")
      .def("__repr__", [](const SceneSource& s) {
        return "<carom.Scene " + s.scene().name + " (" + s.scene().file + ", " + std::to_string(s.assignments().size()) +
               " changes)>";
      });
}

}  // namespace carom::python
