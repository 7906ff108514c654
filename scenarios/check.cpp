#include "check.hpp"

#include <cmath>
#include <sstream>

#include "core/cell_grid.hpp"
#include "enskog.hpp"

namespace carom {

namespace {
std::string vec(const Vec3& v) {
  std::string text("[");
  for (int k = 0; k < 3; ++k) {
    text += format_number(v[k]);
    text += k < 2 ? ", " : "]";
  }
  return text;
}
std::string law_text(const ContactLaw& law) {
  std::string text = "e = " + format_number(law.restitution) + ", mu = " + format_number(law.friction) +
                     ", beta0 = " + format_number(law.tangential_restitution);
  if (law.static_friction >= 0) text += ", mu_static = " + format_number(law.static_friction);
  return text;
}
}  // namespace

std::string describe_scene(const Scene& scene) {
  const System& system = scene.system;
  const ParticleStore& p = system.particles;
  const std::size_t S = system.species.size(), W = system.walls.size();
  std::ostringstream out;
  out << "scene \"" << scene.name << "\" (" << scene.file << ")\n";
  if (!scene.description.empty()) out << "  " << scene.description << "\n";

  const Domain& d = system.domain;
  out << "\ndomain: " << vec(d.lower) << " to " << vec(d.upper) << " m, volume " << format_number(d.volume()) << " m^3\n";
  out << "  periodic axes:";
  bool any_periodic = false;
  for (int k = 0; k < 3; ++k)
    if (d.periodic[k]) {
      out << " " << "xyz"[k];
      any_periodic = true;
    }
  out << (any_periodic ? "" : " none") << "\n  walls:";
  for (const Wall& w : system.walls) out << " " << w.name << (w.shape == Wall::Shape::Cylinder ? " (cylinder)" : "");
  out << (W ? "" : " none") << "\n  gravity: " << vec(system.flight.gravity) << " m/s^2\n";

  std::vector<std::size_t> count(S, 0);
  for (std::uint32_t s : p.species) ++count[s];
  double solid = 0.0;
  out << "\nspecies:\n";
  for (std::size_t s = 0; s < S; ++s) {
    const Species& sp = system.species[s];
    solid += static_cast<double>(count[s]) * sp.volume();
    out << "  " << sp.name << ": d = " << format_number(sp.diameter) << " m, rho = " << format_number(sp.density)
        << " kg/m^3, m = " << format_number(sp.mass()) << " kg, " << count[s] << " particles";
    if (scene.fills[s]) {
      const Fill& f = *scene.fills[s];
      out << " (" << (f.arrangement == Fill::Arrangement::Random ? "random" : f.arrangement == Fill::Arrangement::Fcc ? "fcc" : "cubic")
          << " in region \"" << scene.regions[f.region].name << "\")";
    }
    out << "\n";
  }
  out << "  total " << p.size() << " particles, solid volume fraction of the domain " << format_number(solid / d.volume()) << "\n";
  if (scene.temperature > 0) out << "  initial granular temperature " << format_number(scene.temperature) << " J (Maxwellian)\n";
  if (scene.rms_velocity > 0) out << "  initial rms velocity " << format_number(scene.rms_velocity) << " m/s (Maxwellian)\n";

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
  out << "  gas coupling: none (no [gas] section; particles move in vacuum)\n";
  out << "  flight: ballistic (exact parabolas between events)\n";
  out << "  rotation: " << (friction ? "on (some mu > 0: collisions exchange spin)" : "off (every mu = 0: smooth spheres, spins never change)") << "\n";
  const CollapseOptions& c = scene.options.collapse;
  if (c.contact_time > 0)
    out << "  inelastic collapse: TC model, collisions within " << format_number(c.contact_time) << " s of a particle's previous one are elastic\n";
  else if (dissipative && (system.flight.has_gravity()))
    out << "  inelastic collapse: no remedy, and the scene is dissipative under gravity: a bed at rest WILL collapse; consider [collisions] collapse = { model = \"tc\", contact_time = ... }\n";
  else
    out << "  inelastic collapse: no remedy" << (dissipative ? " (dissipative: clusters may collapse in long runs)" : " (elastic: none needed)") << "\n";
  if (c.elastic_below_speed > 0) out << "  impacts slower than " << format_number(c.elastic_below_speed) << " m/s are elastic\n";

  if (p.size() > 0) {
    HierarchicalGrid grid(d, p.radius, scene.options.grid_level_ratio);
    out << "  neighbour grid: " << grid.levels().size() << " level" << (grid.levels().size() > 1 ? "s" : "")
        << " (a new level below " << format_number(scene.options.grid_level_ratio) << " x the diameter above)\n";
    for (std::size_t l = 0; l < grid.levels().size(); ++l) {
      const auto& level = grid.levels()[l];
      out << "    level " << l << ": " << level.cells[0] << " x " << level.cells[1] << " x " << level.cells[2]
          << " cells of " << vec(level.cell_size) << " m, largest radius " << format_number(level.max_radius) << " m\n";
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
        out << "  " << system.species[s].name << " with " << system.species[t].name << ": " << format_number(nu)
            << " collisions/s per " << system.species[s].name << " particle (g = " << format_number(contact_value(mixture, s, t)) << ")\n";
      }
    out << "  at T = " << format_number(temperature) << " J: " << format_number(total) << " collisions/s in all";
    if (!dissipative) out << ", about " << format_number(total * scene.end_time) << " collisions by t = " << format_number(scene.end_time) << " s";
    else out << " at the start (the gas cools)";
    out << "\n";
  }
  out << "\nrun: to t = " << format_number(scene.end_time) << " s; snapshots every " << format_number(scene.output.snapshot_every)
      << " s, samples every " << format_number(scene.output.sample_every) << " s, checkpoints "
      << (scene.output.checkpoint_every > 0 ? "every " + format_number(scene.output.checkpoint_every) + " s" : std::string("at the end"))
      << "; seed " << scene.seed << "\n";
  return out.str();
}

}  // namespace carom
