#include "scenarios/scene/flow_scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace carom {

namespace {

int read_axis(TableReader& t) {
  const std::string axis = t.required_string("axis", {"x", "y", "z"});
  return axis == "x" ? 0 : axis == "y" ? 1 : 2;
}

int read_plane_side(TableReader& t, const std::string& meaning) {
  if (!t.has("side")) t.fail("side", "is missing (" + meaning + "; allowed: \"above\", \"below\")");
  return t.required_string("side", {"above", "below"}) == "above" ? 1 : -1;
}

/// The name of flow k ("inflow_1", ...) unless the table gives one; unique among `names`.
std::string read_name(TableReader& t, const std::string& what, std::size_t k,
                      const std::vector<std::string>& names) {
  const std::string name = t.string("name", what + "_" + std::to_string(k + 1));
  if (name.empty()) t.fail("name", "is empty");
  for (const std::string& other : names)
    if (other == name) t.fail("name", "is the name of an earlier " + what + "; give each its own");
  return name;
}

/// [flow] interval: the gas step with a gas (a whole multiple of it), else 1e-3 s.
double read_interval(TableReader& root, const Scene& scene) {
  const bool gas = scene.gas.coupling != CouplingLevel::None;
  const double fallback = gas ? scene.gas.time_step : 1e-3;
  auto f = root.table("flow");
  if (!f) return fallback;
  const double interval = f->number(
      "interval", fallback,
      Range::positive("time between flow steps (removals and insertions), s (default: the gas "
                      "time step with a gas, else 1e-3)"));
  if (gas && f->has("interval")) {
    const double steps = interval / scene.gas.time_step;
    if (std::round(steps) < 1.0 || std::abs(steps - std::round(steps)) > 1e-9 * steps)
      f->fail("interval",
              "must be a whole multiple of the gas time step gas.time_step = " +
                  format_number(scene.gas.time_step) + " s (the flow step is a fluid step), e.g. " +
                  format_number(std::max(1.0, std::round(steps)) * scene.gas.time_step));
  }
  f->finish();
  return interval;
}

/// Fails at the key a check named (the table when the check's key is not in it).
[[noreturn]] void fail_at(TableReader& t, const FlowProblem& p) {
  t.fail(p.key, p.problem);
}

}  // namespace

void read_flow(TableReader& root, Scene& scene) {
  FlowSettings& flow = scene.flow;
  flow.interval = read_interval(root, scene);
  const Domain& domain = scene.system.domain;
  std::vector<TableReader> outflow_tables = root.tables("outflow");
  std::vector<std::string> names;
  for (std::size_t k = 0; k < outflow_tables.size(); ++k) {
    TableReader& t = outflow_tables[k];
    Outflow out;
    out.name = read_name(t, "outflow", k, names);
    out.axis = read_axis(t);
    out.plane = t.number("plane", Range::any("position of the outlet plane on its axis, m"));
    out.direction = read_plane_side(t, "which centres leave: those above or below the plane");
    if (auto problem = check_outflow(out, domain)) fail_at(t, *problem);
    t.finish();
    names.push_back(out.name);
    flow.outflows.push_back(out);
  }
  names.clear();
  std::vector<TableReader> inflow_tables = root.tables("inflow");
  for (std::size_t k = 0; k < inflow_tables.size(); ++k) {
    TableReader& t = inflow_tables[k];
    Inflow in;
    in.name = read_name(t, "inflow", k, names);
    in.species = species_index(t, "species", scene);
    in.axis = read_axis(t);
    in.plane = t.number("plane", Range::any("position of the inlet plane on its axis, m"));
    in.direction = read_plane_side(t, "the side of the plane the slab of entering particles lies on");
    in.lower = t.required_vector3(
        "min", Range::any("lower corner of the inlet rectangle, m (the plane's axis is ignored)"));
    in.upper = t.required_vector3(
        "max", Range::any("upper corner of the inlet rectangle, m (the plane's axis is ignored)"));
    in.mass_flow =
        t.number("mass_flow", Range::positive("mass flow rate of entering particles, kg/s"));
    in.velocity =
        t.vector3("velocity", Vec3::Zero(), Range::any("mean velocity of entering particles, m/s"));
    in.velocity_spread = t.vector3(
        "velocity_spread", Vec3::Zero(),
        Range::non_negative("standard deviation of each velocity component (Gaussian), m/s"));
    in.depth = t.number("depth", 0.0,
                        Range::non_negative("slab thickness from the plane, m (0: max(2 d, |v_n| "
                                            "flow.interval + d))"));
    in.attempts = static_cast<int>(
        t.integer("attempts", 100, 1, 1000000, "random tries per particle at one flow step"));
    if (auto problem = check_inflow(in, scene.system, flow.interval)) fail_at(t, *problem);
    const double depth = inflow_depth(in, scene.system.species[in.species], flow.interval);
    for (const Outflow& out : flow.outflows)
      if (auto problem = check_inflow_against_outflow(in, depth, out)) fail_at(t, *problem);
    t.finish();
    names.push_back(in.name);
    flow.inflows.push_back(in);
    // The methods size their steps and grids for what enters (System::entering_species): the
    // species, and the fastest entering speed (mean plus three standard deviations).
    std::vector<std::uint32_t>& entering = scene.system.entering_species;
    if (std::find(entering.begin(), entering.end(), in.species) == entering.end())
      entering.push_back(in.species);
    scene.system.entering_speed =
        std::max(scene.system.entering_speed, in.velocity.norm() + 3.0 * in.velocity_spread.norm());
  }
}

}  // namespace carom
