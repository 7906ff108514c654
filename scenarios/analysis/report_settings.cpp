#include "scenarios/analysis/report_settings.hpp"

#include <algorithm>
#include <sstream>

#include "core/display_number.hpp"
#include "scenarios/analysis/chart_evidence.hpp"

namespace carom {

namespace {

/// The method's own settings, one bullet.
std::string method_settings(const Scene& scene) {
  const MethodSettings& m = scene.method;
  std::ostringstream out;
  switch (m.kind) {
    case MethodKind::EventDriven: {
      const CollapseOptions& c = m.event_driven.collapse;
      out << "- Method: event-driven hard spheres; ";
      if (c.contact_time > 0)
        out << "TC model with a TC time of " << display_number(c.contact_time)
            << " s (collisions.collapse.contact_time): a collision within it of a particle's last "
               "one is elastic and smooth.";
      else
        out << "no TC model (every collision follows the impact law).";
      if (c.elastic_below_speed > 0)
        out << " Impacts slower than " << display_number(c.elastic_below_speed) << " m/s are elastic.";
      break;
    }
    case MethodKind::SoftSphere: {
      const SoftSphereOptions& s = m.soft_sphere;
      out << "- Method: soft spheres (" << (s.model == ContactModel::Linear ? "linear spring-dashpot" : "Hertz-Mindlin")
          << "); step " << (s.time_step > 0 ? display_number(s.time_step) + " s" : std::string("chosen from the contact time"));
      if (s.model == ContactModel::HertzMindlin) {
        out << "; Young's modulus";
        for (std::size_t k = 0; k < s.species_materials.size() && k < scene.system.species.size(); ++k)
          out << (k ? "," : "") << " " << scene.system.species[k].name << " " << display_number(s.species_materials[k].young_modulus)
              << " Pa";
        out << " (a softer contact lasts longer: collision counts and dense-bed dynamics move with it)";
      }
      out << ".";
      break;
    }
    case MethodKind::MonteCarlo: {
      const MonteCarloOptions& mc = m.monte_carlo;
      out << "- Method: Monte Carlo collisions; step "
          << (mc.time_step > 0 ? display_number(mc.time_step) + " s" : std::string("0.1 of the shortest mean free time"))
          << ", collision cells of " << (mc.cell_size > 0 ? display_number(mc.cell_size) + " m" : std::string("about 4 largest diameters"))
          << ", contact value " << (mc.contact_value == ContactValue::Enskog ? "Enskog" : "none (dilute)") << ".";
      break;
    }
  }
  return out.str();
}

/// The gas grid, step and closure, one bullet; empty without a gas.
std::string gas_settings(const Scene& scene) {
  const GasSettings& g = scene.gas;
  if (g.coupling == CouplingLevel::None) return "";
  double largest = 0;
  for (const Species& s : scene.system.species) largest = std::max(largest, s.diameter);
  const Domain& box = scene.system.domain;
  std::ostringstream out;
  out << "- Gas: " << g.cells[0] << " x " << g.cells[1] << " x " << g.cells[2] << " cells (";
  for (int a = 0; a < 3; ++a)
    out << (a ? " x " : "") << display_number((box.upper[a] - box.lower[a]) / g.cells[a] / largest);
  out << " largest diameters), fluid step " << display_number(g.time_step) << " s, drag closure "
      << drag_closure_name(g.closure) << ".";
  return out.str();
}

}  // namespace

std::string numerical_settings_section(const Scene& scene) {
  std::ostringstream r;
  r << "## What these numbers depend on\n\n" << method_settings(scene) << "\n";
  if (const std::string gas = gas_settings(scene); !gas.empty()) r << gas << "\n";
  r << "- Impacts: collisions faster than v* = " << display_number(scene.system.impact_speed)
    << " m/s (analysis.impact_speed"
    << (scene.system.impact_speed > 0 ? "; the default is 0.1 sqrt(g d) with d the smallest diameter"
                                      : "; 0: every collision is an impact")
    << "). A larger v* counts fewer of a dense bed's slow collisions.\n";
  r << "- Seed: initial.seed = " << scene.seed
    << ", one run. Its numbers carry the noise of one seed, which a single run cannot measure: "
       "run a sweep over seeds (scenarios/guides/sweeps.md) for their standard errors.\n\n";
  if (scene.method.kind == MethodKind::EventDriven && scene.method.event_driven.collapse.contact_time > 0) {
    namespace e = evidence;
    r << "In a dense bed the collision counts and the mixing depend on the TC time: each shorter "
         "TC time resolves more of a cluster's impacts one by one. Measured on the main job's bed ("
      << e::kFinesBedTc.file << ", " << e::kFinesBedTcSeeds << " seeds, " << e::kFinesBedTc.record
      << "): from a TC time of " << display_number(e::kFinesBedTcShipped) << " s to " << display_number(e::kFinesBedTcShortest)
      << " s the large beads' mixing rate rose from " << display_number(e::kFinesBedTcMixingShipped) << " to "
      << display_number(e::kFinesBedTcMixingShortest) << " 1/s and their collision frequency with each other from "
      << display_number(e::kFinesBedTcLargeLargeShipped) << " to " << display_number(e::kFinesBedTcLargeLargeShortest)
      << " 1/s; the mixing rate at " << display_number(e::kFinesBedTcConverged) << " s was within the seeds' noise of "
      << display_number(e::kFinesBedTcShortest) << " s. So in a dense bed the raw collision frequencies above are "
         "not converged in the TC time, and a mixing rate at a TC time above "
      << display_number(e::kFinesBedTcConverged) << " s is not shown converged. The impact frequencies moved "
         "far less between "
      << display_number(e::kFinesBedTcConverged) << " and " << display_number(e::kFinesBedTcShortest)
      << " s (large-large " << std::showpos << 100 * e::kFinesBedTcImpactLargeLarge << " %, large-fines "
      << 100 * e::kFinesBedTcImpactLargeFines << " %, fines-fines " << 100 * e::kFinesBedTcImpactFinesFines
      << " %) than the raw large-large count (" << 100 * e::kFinesBedTcRawLargeLargeStep << std::noshowpos
      << " %).\n\n";
  }
  return r.str();
}

}  // namespace carom
