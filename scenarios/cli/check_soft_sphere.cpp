#include "scenarios/cli/check_soft_sphere.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "events/soft_sphere/engine.hpp"

namespace carom {

namespace {

/// Four significant digits: enough for a person reading `carom check`.
std::string short_number(double x) {
  std::ostringstream out;
  out.precision(4);
  out << x;
  return out.str();
}

}  // namespace

void describe_soft_sphere(const Scene& scene, std::ostream& out) {
  const SoftSphereOptions& o = scene.method.soft_sphere;
  out << "  method: soft-sphere DEM, "
      << (o.model == ContactModel::Linear ? "linear spring-dashpot"
                                          : std::string("Hertz–Mindlin, damping ") +
                                                (o.damping == HertzDamping::Exact ? "exact for e" : "LIGGGHTS' formula"))
      << (o.rolling_friction > 0 ? ", rolling resistance " + short_number(o.rolling_friction) : std::string())
      << "\n";
  if (scene.system.particles.size() == 0) return;
  try {
    const SoftSphereEngine sim(scene.system, o);
    const double dt = sim.time_step();
    out << "  time step " << short_number(dt) << " s"
        << (o.time_step > 0 ? " (given)"
                            : " (" + short_number(o.step_fraction) + " x the shortest contact time, " +
                                  short_number(sim.shortest_contact_time()) + " s)")
        << ", impact speed " << short_number(sim.impact_speed()) << " m/s"
        << (o.impact_speed > 0 ? " (given)" : " (estimated)") << ", "
        << short_number(std::ceil(scene.end_time / dt)) << " steps to the end\n";
    const std::size_t S = scene.system.species.size();
    for (std::size_t s = 0; s < S; ++s)
      for (std::size_t t = s; t < S; ++t) {
        const PairContact& c = sim.pair_contact(s, t);
        if (!(c.reduced_mass > 0)) continue;
        const double v = sim.impact_speed();
        out << "    " << scene.system.species[s].name << "-" << scene.system.species[t].name << ": contact time "
            << short_number(c.contact_time(v)) << " s, peak overlap "
            << short_number(c.peak_overlap(v) / std::min(scene.system.species[s].radius(), scene.system.species[t].radius()))
            << " of the smaller radius at " << short_number(v) << " m/s\n";
      }
  } catch (const std::exception& e) {
    out << "  the soft-sphere method cannot run this scene: " << e.what() << "\n";
  }
}

}  // namespace carom
