#include "scenarios/scene/gas_scene.hpp"

#include <algorithm>
#include <limits>

#include "fluid/drag.hpp"
#include "fluid/spin_forces.hpp"

namespace carom {

namespace {

/// The drag closures of fluid/drag.hpp, by scene name.
std::vector<std::string> closure_names() {
  const auto& names = drag_closure_names();
  return {names.begin(), names.end()};
}

/// The names of an array of string_views, as the strings TableReader::string checks against.
template <std::size_t N>
std::vector<std::string> names_of(const std::array<std::string_view, N>& names) {
  return {names.begin(), names.end()};
}

GasSide read_side(TableReader& sides, const std::string& name) {
  GasSide side;
  static const std::vector<std::string> kinds{"wall", "free_slip", "inlet", "outlet"};
  auto kind_of = [](const std::string& k) {
    return k == "wall"     ? GasSide::Kind::Wall
           : k == "inlet"  ? GasSide::Kind::Inlet
           : k == "outlet" ? GasSide::Kind::Outlet
                           : GasSide::Kind::FreeSlip;
  };
  if (!sides.has(name)) return side;
  if (sides.is_string(name)) {
    const std::string k = sides.string(name, "free_slip", kinds);
    if (k == "inlet")
      sides.fail(
          name,
          "needs a velocity: write { type = \"inlet\", velocity = U } (superficial velocity, m/s)");
    side.kind = kind_of(k);
    return side;
  }
  auto t = sides.table(name);
  side.kind = kind_of(t->required_string("type", kinds));
  if (side.kind == GasSide::Kind::Inlet) {
    side.velocity =
        t->number("velocity", Range::any("superficial gas velocity into the domain, m/s"));
    side.ramp_time =
        t->number("ramp_time", 0.0,
                  Range::non_negative("time over which the inlet velocity rises from 0, s"));
    for (TableReader& j : t->tables("jets")) {
      InletJet jet;
      const Vec3 lower =
          j.required_vector3("min", Range::any("lower corner of the jet on the inlet face, m"));
      const Vec3 upper =
          j.required_vector3("max", Range::any("upper corner of the jet on the inlet face, m"));
      const int axis =
          static_cast<int>(std::find(gas_side_names().begin(), gas_side_names().end(), name) -
                           gas_side_names().begin()) /
          2;
      int m = 0;
      for (int k = 0; k < 3; ++k) {
        if (k == axis) continue;
        jet.lower[m] = lower[k];
        jet.upper[m] = upper[k];
        if (!(upper[k] > lower[k])) j.fail("max", "must exceed min on the face's axes");
        ++m;
      }
      jet.velocity = j.number("velocity", Range::any("superficial gas velocity of the jet, m/s"));
      j.finish();
      side.jets.push_back(jet);
    }
  } else if (side.kind == GasSide::Kind::Outlet) {
    side.pressure = t->number("pressure", 0.0, Range::any("outlet pressure, Pa"));
  }
  t->finish();
  return side;
}

CouplingLevel coupling_of(const std::string& name) {
  return name == "two_way"   ? CouplingLevel::TwoWay
         : name == "one_way" ? CouplingLevel::OneWay
                             : CouplingLevel::None;
}

}  // namespace

void read_flight_and_gas(TableReader& root, Scene& scene) {
  std::string model = "ballistic";
  std::string model_where = root.where();
  bool model_given = false;
  if (auto f = root.table("flight")) {
    model_given = f->has("model");
    model = f->string("model", "ballistic", {"ballistic", "relax", "kick"});
    model_where = f->where_key("model");
    scene.flight.particle_step = f->number(
        "particle_step", 0.0,
        Range::non_negative("kick flights: time between drag kicks dt_p, s (0: the fluid step)"));
    if (f->has("particle_step") && model != "kick")
      f->fail("particle_step", "is only used with model = \"kick\"");
    f->finish();
  }
  GasSettings& gas = scene.gas;
  std::string spin_where;  // where the first spin force was switched on, for the error below
  std::string spin_key;
  auto g = root.table("gas");
  if (g) {
    gas.coupling = coupling_of(g->string("coupling", "two_way", {"none", "one_way", "two_way"}));
    gas.density = g->number("density", gas.density, Range::positive("gas density rho_g, kg/m^3"));
    gas.viscosity =
        g->number("viscosity", gas.viscosity, Range::positive("gas viscosity mu_g, Pa s"));
    const Vec3 cells = g->required_vector3(
        "cells", Range{1.0, 1e6, false, false, "gas cells per axis (whole numbers)"});
    for (int k = 0; k < 3; ++k) {
      if (cells[k] != std::floor(cells[k]))
        g->fail("cells", "must be whole numbers of cells per axis");
      gas.cells[k] = static_cast<int>(cells[k]);
    }
    gas.time_step = g->number("time_step", gas.time_step, Range::positive("fluid time step dt, s"));
    gas.closure = parse_drag_closure(
        g->string("drag", std::string(drag_closure_name(gas.closure)), closure_names()));
    gas.fluidization_porosity = g->number("fluidization_porosity", gas.fluidization_porosity,
                                          Range{0.0, 1.0, true, true,
                                                "porosity at minimum fluidization eps_mf "
                                                "(Richardson-Zaki exponent of schiller_naumann)"});
    gas.min_porosity =
        g->number("min_porosity", gas.min_porosity,
                  Range{0.0, 1.0, true, true, "lowest porosity the mapping gives a cell"});
    gas.spin_forces.lift = parse_magnus_lift(
        g->string("magnus_lift", "none", names_of(magnus_lift_names())));
    gas.spin_forces.torque = parse_rotational_torque(
        g->string("rotational_torque", "none", names_of(rotational_torque_names())));
    for (const char* key : {"rotational_torque", "magnus_lift"})
      if (g->has(key) && g->string(key, "none") != "none") {
        spin_where = g->where_key(key);
        spin_key = g->key_path(key);
      }
    const Domain& d = scene.system.domain;
    auto sides = g->table("boundaries");
    for (int s = 0; s < 6; ++s) {
      const std::string& name = gas_side_names()[s];
      if (d.periodic[s / 2]) {
        if (sides && sides->has(name))
          sides->fail(
              name,
              "is on a periodic axis of the domain: the gas is periodic there too; remove it");
        gas.sides[s].kind = GasSide::Kind::Periodic;
      } else if (sides) {
        gas.sides[s] = read_side(*sides, name);
      }
    }
    if (sides) sides->finish();
    g->finish();
  }
  const bool coupled = gas.coupling != CouplingLevel::None;
  scene.flight.model = model == "relax"  ? FlightModel::Relax
                       : model == "kick" ? FlightModel::Kick
                                         : FlightModel::Ballistic;
  if (coupled && !model_given) scene.flight.model = FlightModel::Relax;
  if (!coupled && scene.flight.model != FlightModel::Ballistic)
    throw SceneError(model_where + ": flight.model = \"" + model +
                     "\" needs a gas to drag the particles: add a [gas] section with coupling = "
                     "\"one_way\" or \"two_way\", or use \"ballistic\"");
  if (coupled && model_given && scene.flight.model == FlightModel::Ballistic)
    throw SceneError(
        model_where +
        ": flight.model = \"ballistic\" ignores the gas of [gas]; use \"relax\" (exact drag "
        "flights) or \"kick\" (explicit drag kicks), or set gas.coupling = \"none\"");
  // Spin forces are kicks: a relax flight is the exact solution of a = drive - rate v, linear in
  // v, which is what makes it analytic and lets the event predictions bound each particle's
  // velocity on the segment from v0 to the terminal velocity. The lift, |u - v| C_L(Re, Gamma)
  // (Omega x (u - v)) / |Omega|, is not linear in v, turns the velocity out of that segment and
  // couples it to a spin that the torque slows non-linearly: no closed-form flight is left and
  // the contact-time bounds fail. Kick flights take them as explicit impulses every dt_p.
  if (gas.spin_forces.any() && scene.flight.model != FlightModel::Kick)
    throw SceneError(spin_where + ": " + spin_key + " needs flight.model = \"kick\" (the spin "
                     "forces are applied as explicit kicks every flight.particle_step); with \"" +
                     std::string(scene.flight.model == FlightModel::Relax ? "relax" : "ballistic") +
                     "\" flights the lift would make the exact flight non-analytic (it is not "
                     "linear in the velocity and turns it off the path the event predictions "
                     "bound). Set [flight] model = \"kick\" (methods event_driven and "
                     "monte_carlo; soft spheres take no spin forces), or " + spin_key +
                     " = \"none\"");
  if (scene.flight.model == FlightModel::Kick && scene.flight.particle_step == 0.0)
    scene.flight.particle_step = gas.time_step;
  // Kick flights are ballistic between the kicks (the kicks are the gas coupling's).
  scene.method.event_driven.flight_model =
      scene.flight.model == FlightModel::Relax ? FlightModel::Relax : FlightModel::Ballistic;
}

}  // namespace carom
