// carom.Simulation: a scene stepped in process, its state read between steps as numpy arrays
// (copies). Particle arrays are in the order of the particle ids, as the run file's snapshots.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <functional>

#include "events/flow/flow_boundaries.hpp"
#include "fluid/coupling.hpp"
#include "scenarios/python/bindings.hpp"
#include "scenarios/python/scene_source.hpp"
#include "scenarios/python/simulation.hpp"

namespace py = pybind11;

namespace carom::python {

namespace {

/// One value per particle, in id order: (N,) or (N, 3) for vectors.
template <typename T>
py::array_t<T> per_particle(const Simulation& sim, const std::function<T(std::size_t)>& value) {
  const std::vector<std::size_t> order = sim.id_order();
  py::array_t<T> array(static_cast<py::ssize_t>(order.size()));
  auto out = array.template mutable_unchecked<1>();
  for (std::size_t k = 0; k < order.size(); ++k) out(static_cast<py::ssize_t>(k)) = value(order[k]);
  return array;
}

py::array_t<double> per_particle_vector(const Simulation& sim, const std::function<Vec3(std::size_t)>& value) {
  const std::vector<std::size_t> order = sim.id_order();
  py::array_t<double> array({static_cast<py::ssize_t>(order.size()), py::ssize_t{3}});
  auto out = array.mutable_unchecked<2>();
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Vec3 v = value(order[k]);
    for (py::ssize_t c = 0; c < 3; ++c) out(static_cast<py::ssize_t>(k), c) = v[c];
  }
  return array;
}

/// A gas field of one value (components 0) or `components` values per cell, shaped as in the run
/// file: (nz, ny, nx) or (nz, ny, nx, components), x varying fastest.
py::array_t<double> gas_field(const GasCoupling& gas, const double* values, py::ssize_t components) {
  const std::array<int, 3> cells = gas.cells();
  std::vector<py::ssize_t> shape{cells[2], cells[1], cells[0]};
  if (components > 0) shape.push_back(components);
  py::array_t<double> array(shape);
  std::copy(values, values + array.size(), array.mutable_data());
  return array;
}

const GasCoupling& gas_of(const Simulation& sim) {
  if (sim.gas() == nullptr) throw py::value_error("this scene has no coupled gas ([gas] coupling = \"none\")");
  return *sim.gas();
}

template <typename T>
py::array_t<T> matrix(const std::vector<T>& values, std::size_t rows, std::size_t columns) {
  py::array_t<T> array({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(columns)});
  std::copy(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rows * columns), array.mutable_data());
  return array;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<Simulation>(m, "Simulation",
                         "A scene stepped in process by the method `carom run` would use, with its gas, "
                         "inflows and outflows. advance(t) runs on; the state is read between steps.")
      .def(py::init([](const SceneSource& source) {
             const py::gil_scoped_release unlocked;
             return std::make_unique<Simulation>(source.scene());
           }),
           py::arg("scene"), "Places the particles (and settles them) and starts the method at t = 0.")
      .def_static(
          "restore",
          [](const std::string& path) {
            const py::gil_scoped_release unlocked;
            return std::make_unique<Simulation>(Simulation::restore(path));
          },
          py::arg("checkpoint"),
          "Continues from a checkpoint (a run's checkpoint.h5, or one written by checkpoint()) with the "
          "scene stored in it, bit for bit as `carom resume` does.")
      .def(
          "advance",
          [](Simulation& sim, double t) {
            bool reached = false;
            {
              const py::gil_scoped_release unlocked;
              reached = sim.advance(t);
            }
            if (!reached) {
              PyErr_SetString(PyExc_KeyboardInterrupt, "stopped by a signal at a consistent state; advance again to go on");
              throw py::error_already_set();
            }
            return sim.time();
          },
          py::arg("t"),
          "Runs to time t (s) and returns the time reached. The event-driven and Monte Carlo "
          "methods stop exactly at t without changing the run; soft spheres cut their last step "
          "to land on t unless t is a step boundary (stop_time(t) gives the next one), as `carom "
          "run` does at an output instant. Ctrl-C stops it at a consistent state "
          "(KeyboardInterrupt); advance again to go on.")
      .def("stop_time", &Simulation::stop_time, py::arg("t"),
           "The earliest time >= t at which the method can stop without changing the run: t for "
           "the event-driven and Monte Carlo methods, the next step boundary (or synchronising "
           "action) for soft spheres.")
      .def_property_readonly("time", &Simulation::time, "The current time, s.")
      .def_property_readonly("method", [](const Simulation& sim) { return std::string(sim.method().kind()); })
      .def_property_readonly("scene_text", [](const Simulation& sim) { return sim.scene().text; })
      .def_property_readonly("particle_count", [](const Simulation& sim) { return sim.method().particle_count(); })
      .def_property_readonly("species_names", [](const Simulation& sim) {
        std::vector<std::string> names;
        for (const Species& s : sim.method().system().species) names.push_back(s.name);
        return names;
      })
      .def_property_readonly("wall_names", [](const Simulation& sim) {
        std::vector<std::string> names;
        for (const Wall& w : sim.method().system().walls) names.push_back(w.name);
        return names;
      })
      .def("positions", [](const Simulation& sim) {
        return per_particle_vector(sim, [&](std::size_t i) { return sim.method().position(i); });
      }, "(N, 3) positions, m, in id order.")
      .def("velocities", [](const Simulation& sim) {
        return per_particle_vector(sim, [&](std::size_t i) { return sim.method().velocity(i); });
      }, "(N, 3) velocities, m/s, in id order.")
      .def("spins", [](const Simulation& sim) {
        return per_particle_vector(sim, [&](std::size_t i) { return sim.method().spin(i); });
      }, "(N, 3) angular velocities, rad/s, in id order.")
      .def("radii", [](const Simulation& sim) {
        const ParticleStore& p = sim.method().system().particles;
        return per_particle<double>(sim, [&](std::size_t i) { return p.radius[i]; });
      }, "(N,) radii, m, in id order.")
      .def("species", [](const Simulation& sim) {
        const ParticleStore& p = sim.method().system().particles;
        return per_particle<std::int32_t>(sim, [&](std::size_t i) { return static_cast<std::int32_t>(p.species[i]); });
      }, "(N,) species indices (into species_names), in id order.")
      .def("ids", [](const Simulation& sim) {
        const ParticleStore& p = sim.method().system().particles;
        return per_particle<std::int64_t>(sim, [&](std::size_t i) { return static_cast<std::int64_t>(p.id[i]); });
      }, "(N,) particle ids, ascending.")
      .def("energies", [](const Simulation& sim) {
        const Energies e = sim.method().energies();
        return py::dict(py::arg("translational") = e.translational, py::arg("rotational") = e.rotational,
                        py::arg("potential") = e.potential, py::arg("elastic") = e.elastic,
                        py::arg("dissipated") = e.dissipated, py::arg("gas_work") = e.gas_work,
                        py::arg("flow") = e.flow, py::arg("total") = e.total());
      }, "Energies now, J (dissipated, gas_work and flow: since t = 0; total: their balance, constant "
         "in an exact run).")
      .def("collisions", [](const Simulation& sim) {
        const RunStatistics& s = sim.method().statistics();
        py::array_t<double> wall_impulse({static_cast<py::ssize_t>(s.wall_count), py::ssize_t{3}});
        for (std::size_t w = 0; w < s.wall_count; ++w)
          for (int c = 0; c < 3; ++c) wall_impulse.mutable_at(w, c) = s.wall_impulse[w][c];
        return py::dict(py::arg("events") = s.events, py::arg("collisions") = s.collisions(),
                        py::arg("pair") = matrix(s.pair_collisions, s.species_count, s.species_count),
                        py::arg("pair_impulse") = matrix(s.pair_impulse, s.species_count, s.species_count),
                        py::arg("wall") = matrix(s.wall_collisions, s.species_count, s.wall_count),
                        py::arg("wall_impulse") = wall_impulse);
      }, "Counts since t = 0: events (time-stepped: steps), collisions, per species pair (S, S), "
         "per species and wall (S, W); impulses, N s.")
      .def("quantities", [](const Simulation& sim) {
        py::dict d;
        for (const MethodQuantity& q : sim.method().quantities())
          d[py::str(q.name)] = py::dict(py::arg("value") = q.value, py::arg("unit") = q.unit, py::arg("what") = q.what);
        return d;
      }, "What the method measures beyond the counts (soft spheres: coordination number, ...).")
      .def_property_readonly("has_gas", [](const Simulation& sim) { return sim.gas() != nullptr; })
      .def("porosity", [](const Simulation& sim) {
        const GasCoupling& gas = gas_of(sim);
        return gas_field(gas, gas.porosity().data(), 0);
      }, "(nz, ny, nx) gas porosity per cell at the last fluid step.")
      .def("pressure", [](const Simulation& sim) {
        const GasCoupling& gas = gas_of(sim);
        return gas_field(gas, gas.pressure_field().data(), 0);
      }, "(nz, ny, nx) gas pressure per cell, Pa.")
      .def("gas_velocity", [](const Simulation& sim) {
        const GasCoupling& gas = gas_of(sim);
        const std::vector<Vec3> velocity = gas.velocity_field();
        std::vector<double> flat;
        for (const Vec3& v : velocity) flat.insert(flat.end(), {v.x(), v.y(), v.z()});
        return gas_field(gas, flat.data(), 3);
      }, "(nz, ny, nx, 3) interstitial gas velocity at the cell centres, m/s.")
      .def("pressure_drop", [](const Simulation& sim) { return gas_of(sim).pressure_drop(); },
           "Mean gas pressure at the bottom of the grid minus that at its top, Pa.")
      .def("gas_grid", [](const Simulation& sim) {
        const GasCoupling& gas = gas_of(sim);
        const Vec3 lower = gas.grid_lower(), size = gas.cell_size();
        return py::dict(py::arg("cells") = gas.cells(), py::arg("lower") = std::vector<double>{lower.x(), lower.y(), lower.z()},
                        py::arg("spacing") = std::vector<double>{size.x(), size.y(), size.z()},
                        py::arg("open_volume") = gas_field(gas, gas.open_volume().data(), 0));
      }, "The gas grid: cells per axis (x, y, z), lower corner and cell size, m, and each cell's "
         "gas volume inside the walls, m^3.")
      .def("checkpoint", [](const Simulation& sim, const std::string& path) {
        const py::gil_scoped_release unlocked;
        sim.checkpoint(path);
      }, py::arg("path"), "Writes a checkpoint of the current state (as `carom run` writes checkpoint.h5).")
      .def("__repr__", [](const Simulation& sim) {
        return "<carom.Simulation " + sim.scene().name + " (" + std::string(sim.method().kind()) + ") at t = " +
               py::repr(py::float_(sim.time())).cast<std::string>() + " s>";
      });
}

}  // namespace carom::python
