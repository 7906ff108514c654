#include "scenarios/cli/check.hpp"
#include "scenarios/cli/check_soft_sphere.hpp"

#include <cmath>
#include <sstream>

#include "core/cell_grid.hpp"
#include "core/display_number.hpp"
#include "scenarios/analysis/enskog.hpp"
#include "fluid/drag.hpp"
#include "events/method_factory.hpp"
#include "scenarios/cli/recommend.hpp"
#include "scenarios/run/output_estimate.hpp"
#include "scenarios/run/run.hpp"
#include "scenarios/scene/settling.hpp"

namespace carom {

namespace {
std::string vec(const Vec3& v) {
  std::string text("[");
  for (int k = 0; k < 3; ++k) {
    text += display_number(v[k]);
    text += k < 2 ? ", " : "]";
  }
  return text;
}
std::string law_text(const ContactLaw& law) {
  std::string text = "e = " + display_number(law.restitution) + ", mu = " + display_number(law.friction) +
                     ", beta0 = " + display_number(law.tangential_restitution);
  if (law.static_friction >= 0) text += ", mu_static = " + display_number(law.static_friction);
  return text;
}
}  // namespace

/// The gas part of the model, with the numbers that say whether it is needed and enough.
static void describe_gas(const Scene& scene, std::ostringstream& out) {
  const GasSettings& gas = scene.gas;
  if (gas.coupling == CouplingLevel::None) {
    out << "  gas coupling: none (no [gas]: particles move in vacuum; right for granular gases and for "
           "particles so heavy or fast that drag does not matter)\n";
    out << "  flight: ballistic (exact parabolas between events)\n";
    return;
  }
  const System& system = scene.system;
  const double g = system.flight.gravity.norm();
  out << "  gas coupling: "
      << (gas.coupling == CouplingLevel::OneWay
              ? "one-way (the gas moves the particles; they neither take its volume nor push it: right "
                "while the solid fraction stays below ~1e-3)"
              : "two-way (porosity in the gas equations, drag reaction on the gas: needed for beds)")
      << "\n";
  out << "  gas: rho_g = " << display_number(gas.density) << " kg/m^3, mu_g = " << display_number(gas.viscosity)
      << " Pa s on " << gas.cells[0] << " x " << gas.cells[1] << " x " << gas.cells[2] << " cells, fluid step "
      << display_number(gas.time_step) << " s, drag closure " << drag_closure_name(gas.closure) << "\n";
  for (int s = 0; s < 6; ++s) {
    const GasSide& side = gas.sides[s];
    if (side.kind == GasSide::Kind::Inlet)
      out << "  inlet " << gas_side_names()[s] << ": superficial velocity " << display_number(side.velocity) << " m/s"
          << (side.ramp_time > 0 ? " (ramped over " + display_number(side.ramp_time) + " s)" : std::string())
          << (side.jets.empty() ? "" : ", with " + std::to_string(side.jets.size()) + " jet(s)") << "\n";
  }
  const DragClosure closure(gas.closure, gas.fluidization_porosity, g > 0 ? g : 9.81);
  for (const Species& sp : system.species) {
    DragInput in;
    in.diameter = in.sauter_diameter = sp.diameter;
    in.gas_density = gas.density;
    in.gas_viscosity = gas.viscosity;
    in.particle_density = sp.density;
    // The species' relaxation time is printed once, with the recommendation below.
    if (g > 0)
      out << "  " << sp.name << ": terminal velocity " << display_number(closure.terminal_velocity(in))
          << " m/s, U_mf " << display_number(closure.minimum_fluidization_velocity(in, 0.4)) << " m/s ("
          << drag_closure_name(gas.closure) << " at eps_mf = 0.4; Wen-Yu correlation "
          << display_number(wen_yu_minimum_fluidization_velocity(in, g)) << " m/s)\n";
  }
  if (scene.flight.model == FlightModel::Kick)
    out << "  flight: kick (ballistic, explicit drag kicks every "
        << display_number(scene.flight.particle_step)
        << " s; stable only while that is below 2 m / (dF/ds) of every particle (less than 2 tau), "
           "checked at every fluid step)\n";
  else
    out << "  flight: relax (exact flight under gravity and the drag frozen for each fluid step: stable for any "
           "step, events exact)\n";
}

/// The inflows and outflows ([[inflow]], [[outflow]], [flow]).
static void describe_flow(const Scene& scene, std::ostream& out) {
  const FlowSettings& flow = scene.flow;
  if (!flow.any()) return;
  out << "\nflow (particles entering and leaving at flow steps every " << display_number(flow.interval) << " s):\n";
  for (const Inflow& in : flow.inflows) {
    const Species& sp = scene.system.species[in.species];
    const int a = in.axis, b = (a + 1) % 3, c = (a + 2) % 3;
    out << "  inflow \"" << in.name << "\": " << sp.name << " at " << display_number(in.mass_flow) << " kg/s ("
        << display_number(std::round(in.mass_flow / sp.mass())) << " particles/s) through " << "xyz"[a] << " = "
        << display_number(in.plane) << " m, " << "xyz"[b] << " in [" << display_number(in.lower[b]) << ", "
        << display_number(in.upper[b]) << "], " << "xyz"[c] << " in [" << display_number(in.lower[c]) << ", "
        << display_number(in.upper[c]) << "] m, slab " << display_number(inflow_depth(in, sp, flow.interval)) << " m "
        << (in.direction > 0 ? "above" : "below") << "; velocity " << vec(in.velocity) << " +- "
        << vec(in.velocity_spread) << " m/s\n";
  }
  for (const Outflow& o : flow.outflows)
    out << "  outflow \"" << o.name << "\": centres " << (o.direction > 0 ? "above " : "below ") << "xyz"[o.axis]
        << " = " << display_number(o.plane) << " m leave\n";
}

std::string describe_scene(const Scene& scene) {
  const System& system = scene.system;
  const ParticleStore& p = system.particles;
  const std::size_t S = system.species.size(), W = system.walls.size();
  std::ostringstream out;
  out << "scene \"" << scene.name << "\" (" << scene.file << ")\n";
  if (!scene.description.empty()) out << "  " << scene.description << "\n";

  const Domain& d = system.domain;
  out << "\ndomain: " << vec(d.lower) << " to " << vec(d.upper) << " m, volume " << display_number(d.volume()) << " m^3\n";
  out << "  periodic axes:";
  bool any_periodic = false;
  for (int k = 0; k < 3; ++k)
    if (d.periodic[k]) {
      out << " " << "xyz"[k];
      any_periodic = true;
    }
  out << (any_periodic ? "" : " none") << "\n  walls:";
  for (const Wall& w : system.walls) {
    const std::string shape = w.description();
    out << " " << w.name << (shape.empty() ? "" : " (" + shape + ")");
  }
  out << (W ? "" : " none") << "\n  gravity: " << vec(system.flight.gravity) << " m/s^2\n";

  std::vector<std::size_t> count(S, 0);
  for (std::uint32_t s : p.species) ++count[s];
  double solid = 0.0;
  out << "\nspecies:\n";
  for (std::size_t s = 0; s < S; ++s) {
    const Species& sp = system.species[s];
    solid += static_cast<double>(count[s]) * sp.volume();
    out << "  " << sp.name << ": d = " << display_number(sp.diameter) << " m, rho = " << display_number(sp.density)
        << " kg/m^3, m = " << display_number(sp.mass()) << " kg, " << count[s] << " particles";
    if (scene.fills[s]) {
      const Fill& f = *scene.fills[s];
      out << " (" << (f.arrangement == Fill::Arrangement::Random ? "random" : f.arrangement == Fill::Arrangement::Fcc ? "fcc" : "cubic")
          << " in region \"" << scene.regions[f.region].name << "\")";
    }
    out << "\n";
  }
  out << "  total " << p.size() << " particles, solid volume fraction of the domain " << display_number(solid / d.volume()) << "\n";
  if (scene.temperature > 0) out << "  initial granular temperature " << display_number(scene.temperature) << " J (Maxwellian)\n";
  if (scene.rms_velocity > 0) out << "  initial rms velocity " << display_number(scene.rms_velocity) << " m/s (Maxwellian)\n";

  describe_flow(scene, out);

  out << "\ncontact laws (Walton):\n";
  bool friction = false, dissipative = false;
  for (std::size_t s = 0; s < S; ++s) {
    for (std::size_t t = s; t < S; ++t) {
      const ContactLaw& law = system.materials.pair(s, t);
      friction |= law.friction > 0;
      dissipative |= law.restitution < 1;
      out << "  " << system.species[s].name << "-" << system.species[t].name << ": " << law_text(law) << "\n";
    }
    for (std::size_t w = 0; w < W; ++w) {
      const ContactLaw& law = system.materials.wall(s, w);
      friction |= law.friction > 0;
      dissipative |= law.restitution < 1;
      out << "  " << system.species[s].name << "@" << system.walls[w].name << ": " << law_text(law) << "\n";
    }
  }
  out << "\nmodel:\n";
  describe_gas(scene, out);
  out << "  rotation: " << (friction ? "on (some mu > 0: collisions exchange spin)" : "off (every mu = 0: smooth spheres, spins never change)") << "\n";
  if (scene.method.kind == MethodKind::SoftSphere) describe_soft_sphere(scene, out);
  const CollapseOptions& c = scene.method.event_driven.collapse;
  if (scene.method.kind != MethodKind::EventDriven) {
    // the collapse remedies and the neighbour grid below are the event-driven method's
  } else if (c.contact_time > 0)
    out << "  inelastic collapse: TC model, collisions within " << display_number(c.contact_time) << " s of a particle's previous one are elastic\n";
  else if (dissipative && (system.flight.has_gravity()))
    out << "  inelastic collapse: no remedy, and the scene is dissipative under gravity: a bed at rest WILL collapse; consider [collisions] collapse = { model = \"tc\", contact_time = ... }\n";
  else
    out << "  inelastic collapse: no remedy" << (dissipative ? " (dissipative: clusters may collapse in long runs)" : " (elastic: none needed)") << "\n";
  if (scene.method.kind == MethodKind::EventDriven && c.elastic_below_speed > 0) out << "  impacts slower than " << display_number(c.elastic_below_speed) << " m/s are elastic\n";

  if (p.size() > 0 && scene.method.kind == MethodKind::EventDriven) {
    HierarchicalGrid grid(d, p.radius, scene.method.event_driven.grid_level_ratio,
                          scene.method.event_driven.grid_subdivision);
    const double ratio = scene.method.event_driven.grid_level_ratio;
    out << "  neighbour grid: " << grid.levels().size() << " level" << (grid.levels().size() > 1 ? "s" : "") << " ("
        << (ratio < 0.0   ? std::string("sizes split into levels by the grid's cost model, the split with the least "
                                        "expected prediction work; engine.grid_level_ratio sets a fixed ratio")
            : ratio == 0.0 ? std::string("one grid for every size: engine.grid_level_ratio = 0")
                           : "a diameter below " + display_number(ratio) +
                                 " x the largest of a level starts a new level: engine.grid_level_ratio")
        << ")\n";
    for (std::size_t l = 0; l < grid.levels().size(); ++l) {
      const auto& level = grid.levels()[l];
      out << "    level " << l << ": " << level.cells[0] << " x " << level.cells[1] << " x "
          << level.cells[2] << " cells of " << vec(level.cell_size) << " m, largest radius "
          << display_number(level.max_radius) << " m, block of " << 2 * level.reach + 1
          << "^3 cells\n";
    }
  }

  const bool homogeneous = !system.flight.has_gravity() && W == 0 && d.periodic[0] && d.periodic[1] && d.periodic[2];
  double temperature = scene.temperature;
  if (temperature == 0.0 && p.size() > 0) {
    double kinetic = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) kinetic += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
    temperature = 2.0 * kinetic / (3.0 * static_cast<double>(p.size()));
  }
  out << "\nexpected collision rate (Enskog, BMCSL contact value):\n";
  if (!homogeneous || temperature <= 0.0 || p.size() == 0) {
    out << "  not applicable (needs a periodic, gravity-free box without walls and a non-zero temperature)\n";
  } else {
    std::vector<MixtureComponent> mixture;
    for (std::size_t s = 0; s < S; ++s)
      mixture.push_back({static_cast<double>(count[s]) / d.volume(), system.species[s].diameter, system.species[s].mass()});
    double total = 0.0;
    for (std::size_t s = 0; s < S; ++s)
      for (std::size_t t = 0; t < S; ++t) {
        const double nu = enskog_frequency(mixture, s, t, temperature);
        total += 0.5 * static_cast<double>(count[s]) * nu;
        out << "  " << system.species[s].name << " with " << system.species[t].name << ": " << display_number(nu)
            << " collisions/s per " << system.species[s].name << " particle (g = " << display_number(contact_value(mixture, s, t)) << ")\n";
      }
    out << "  at T = " << display_number(temperature) << " J: " << display_number(total) << " collisions/s in all";
    if (!dissipative) out << ", about " << display_number(total * scene.end_time) << " collisions by t = " << display_number(scene.end_time) << " s";
    else out << " at the start (the gas cools)";
    out << "\n";
  }
  out << "\nrun: to t = " << display_number(scene.end_time) << " s; snapshots every " << display_number(scene.output.snapshot_every)
      << " s, samples every " << display_number(scene.output.sample_every) << " s, checkpoints "
      << (scene.output.checkpoint_every > 0 ? "every " + display_number(scene.output.checkpoint_every) + " s" : std::string("at the end"))
      << "; seed " << scene.seed << "\n";
  const OutputEstimate e = estimate_output(scene, p.size());
  out << "output: about " << byte_text(e.bytes) << " (" << display_number(e.snapshots) << " snapshots of "
      << byte_text(e.snapshot_bytes) << ", " << display_number(e.samples) << " time-series rows of "
      << byte_text(e.sample_bytes) << ", a checkpoint of " << byte_text(e.checkpoint_bytes) << "); a run refuses more than "
      << byte_text(scene.output.max_bytes) << " (output.max_bytes"
      << (scene.output.max_bytes_given ? ")" : ", the default) or more than the free space") << "\n";
  return out.str();
}

std::string wrap_lines(const std::string& text, std::size_t width) {
  std::string wrapped;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    const bool newline = end != std::string::npos;
    if (!newline) end = text.size();
    std::string line = text.substr(begin, end - begin);
    const std::size_t indent = std::min(line.find_first_not_of(' '), line.size());
    const std::string continuation(indent + 4, ' ');
    std::size_t floor = indent;  // no cut inside the indent
    while (line.size() > width) {
      // The last space within the width, else the first one after it (a long word stays whole).
      std::size_t cut = line.rfind(' ', width);
      if (cut == std::string::npos || cut <= floor) cut = line.find(' ', width);
      if (cut == std::string::npos) break;
      std::size_t next = cut;
      while (next < line.size() && line[next] == ' ') ++next;
      if (next == line.size()) break;
      wrapped.append(line, 0, cut);
      wrapped += '\n';
      line = continuation + line.substr(next);
      floor = continuation.size();
    }
    wrapped += line;
    if (newline) wrapped += '\n';
    begin = end + 1;
  }
  return wrapped;
}

void check_scene(Scene scene, bool settle, std::ostream& out) { out << check_report(std::move(scene), settle).text; }

CheckReport check_report(Scene scene, bool settle) {
  const bool settling_skipped = !settle && scene.settle_time > 0;
  if (settling_skipped) scene.settle_time = 0;
  install_stop_handlers();
  build_initial_state(scene, stop_flag());
  if (*stop_flag()) throw InterruptedBeforeStart("interrupted while the particles were placed: nothing checked");
  try {
    make_method(scene.system, scene.method);  // the checks a run makes at its start
  } catch (const std::invalid_argument& e) {
    throw SceneError(scene.file + ": " + e.what());
  }
  CheckReport report;
  std::string text = describe_scene(scene);
  if (settling_skipped)
    text += "\nsettling: initial.settle_time is not run by carom check (carom check --settle runs it); "
            "the particles above are as placed, and the estimates below take them as a bed settled "
            "to a random packing of solid fraction " +
            display_number(kSettledPacking) + "\n";
  report.numbers = scene_numbers(scene, settling_skipped);
  report.advice = recommend(scene, report.numbers);
  text += describe_recommendation(report.numbers, report.advice);
  report.text = wrap_lines(text);
  return report;
}

}  // namespace carom
