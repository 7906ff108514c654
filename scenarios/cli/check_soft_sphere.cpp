#include "scenarios/cli/check_soft_sphere.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "core/display_number.hpp"
#include "events/soft_sphere/engine.hpp"

namespace carom {

void describe_soft_sphere(const Scene& scene, std::ostream& out) {
  const SoftSphereOptions& o = scene.method.soft_sphere;
  out << "  method: soft-sphere DEM, "
      << (o.model == ContactModel::Linear ? "linear spring-dashpot"
                                          : std::string("Hertz–Mindlin, damping ") +
                                                (o.damping == HertzDamping::Exact ? "exact for e" : "LIGGGHTS' formula"))
      << (o.rolling_friction > 0 ? ", rolling resistance " + display_number(o.rolling_friction) : std::string())
      << "\n";
  if (scene.system.particles.size() == 0) return;
  try {
    const SoftSphereEngine sim(scene.system, o);
    const double dt = sim.time_step();
    out << "  time step " << display_number(dt) << " s"
        << (o.time_step > 0 ? " (given)"
                            : " (" + display_number(o.step_fraction) + " x the shortest contact time, " +
                                  display_number(sim.shortest_contact_time()) + " s)")
        << ", impact speed " << display_number(sim.impact_speed()) << " m/s"
        << (o.impact_speed > 0 ? " (given)" : " (estimated)") << ", "
        << display_number(std::ceil(scene.end_time / dt)) << " steps to the end\n";
    const std::size_t S = scene.system.species.size();
    for (std::size_t s = 0; s < S; ++s)
      for (std::size_t t = s; t < S; ++t) {
        const PairContact& c = sim.pair_contact(s, t);
        if (!(c.reduced_mass > 0)) continue;
        const double v = sim.impact_speed();
        out << "    " << scene.system.species[s].name << "-" << scene.system.species[t].name << ": contact time "
            << display_number(c.contact_time(v)) << " s, peak overlap "
            << display_number(c.peak_overlap(v) / std::min(scene.system.species[s].radius(), scene.system.species[t].radius()))
            << " of the smaller radius at " << display_number(v) << " m/s\n";
      }
  } catch (const std::exception& e) {
    out << "  the soft-sphere method cannot run this scene: " << e.what() << "\n";
  }
}

}  // namespace carom
