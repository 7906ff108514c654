// The conclusions of a run's analysis: the "analysis" object of summary.json and report.md.
#include <cmath>
#include <sstream>

#include "scenarios/analysis/dispersion.hpp"
#include "scenarios/analysis/report_settings.hpp"
#include "scenarios/analysis/run_analysis.hpp"
#include "scenarios/run/summary.hpp"

namespace carom {

namespace {

/// "a-b" for a species pair.
std::string pair_name(const System& system, std::size_t s, std::size_t t) {
  return system.species[s].name + "-" + system.species[t].name;
}

/// A number for report.md: 4 significant digits, "n/a" for NaN.
std::string fixed(double x) {
  if (!std::isfinite(x)) return "n/a";
  std::ostringstream out;
  out.precision(4);
  out << x;
  return out.str();
}

/// A diameter for report.md in the unit that reads best: mm from 0.1 mm to 10 cm, else m.
std::string diameter_text(double d) {
  return d >= 1e-4 && d < 0.1 ? fixed(d * 1e3) + " mm" : fixed(d) + " m";
}

/// JSON object {"key": value, ...} from names and values.
std::string object(const std::vector<std::pair<std::string, double>>& entries) {
  std::string text = "{";
  for (std::size_t k = 0; k < entries.size(); ++k)
    text += (k ? ", " : "") + json_string(entries[k].first) + ": " + json_number(entries[k].second);
  return text + "}";
}

}  // namespace

std::string RunAnalysis::summary_json(const CollisionMethod& sim) const {
  const Conclusions c = conclude(sim);
  const System& system = sim.system();
  const std::size_t S = system.species.size();
  std::ostringstream j;
  j << "{\n";
  if (c.mixing) {
    j << "    \"mixing\": {\"species\": "
      << json_string(system.species[scene_.analysis.mixing_species].name)
      << ", \"lacey_start\": " << json_number(c.lacey_start)
      << ", \"lacey_end\": " << json_number(c.lacey_end)
      << ", \"rate\": " << json_number(c.rate.valid ? c.rate.rate : NAN)
      << ", \"fit_start\": " << json_number(c.rate.start)
      << ", \"time_to_m08_fit\": " << json_number(c.rate.valid ? c.rate.time_to_08_fit : NAN)
      << ", \"time_to_m08\": " << json_number(c.rate.time_to_08_data)
      << ", \"fit_rms\": " << json_number(c.rate.rms_residual) << "},\n";
    j << "    \"dispersion\": {\"axial_coefficient\": "
      << json_number(c.dispersion.valid ? c.dispersion.coefficient : NAN)
      << ", \"axial_coefficient_early\": "
      << json_number(c.early_dispersion.valid ? c.early_dispersion.coefficient : NAN)
      << ", \"early_fit_end\": " << json_number(c.early_dispersion.fit_end)
      << ", \"saturation_msd\": " << json_number(c.saturation_msd) << "},\n";
  }
  std::vector<std::pair<std::string, double>> measured, kinetic, impacts, kinetic_impacts, impulse;
  for (std::size_t s = 0; s < S; ++s) {
    for (std::size_t t = 0; t < S; ++t) {
      measured.emplace_back(pair_name(system, s, t), c.measured_rate[s * S + t]);
      kinetic.emplace_back(pair_name(system, s, t), c.kinetic_rate[s * S + t]);
      impacts.emplace_back(pair_name(system, s, t), c.impact_rate[s * S + t]);
      kinetic_impacts.emplace_back(pair_name(system, s, t), c.kinetic_impact_rate[s * S + t]);
      impulse.emplace_back(pair_name(system, s, t),
                           c.weight[s] > 0 ? c.impulse_rate[s * S + t] / c.weight[s] : NAN);
    }
    measured.emplace_back(system.species[s].name + "@walls", c.wall_rate[s]);
    impacts.emplace_back(system.species[s].name + "@walls", c.wall_impact_rate[s]);
  }
  j << "    \"collision_frequency\": " << object(measured) << ",\n";
  j << "    \"kinetic_theory_frequency\": " << object(kinetic) << ",\n";
  j << "    \"impact_speed\": " << json_number(system.impact_speed) << ",\n";
  j << "    \"impact_frequency\": " << object(impacts) << ",\n";
  j << "    \"kinetic_theory_impact_frequency\": " << object(kinetic_impacts) << ",\n";
  std::vector<std::pair<std::string, double>> temperature;
  for (std::size_t s = 0; s < S; ++s)
    temperature.emplace_back(system.species[s].name, c.temperature[s]);
  j << "    \"granular_temperature\": " << object(temperature) << ",\n";
  if (small_ >= 0)
    j << "    \"segregation_index\": "
      << object(std::vector<std::pair<std::string, double>>{{"start", c.segregation_start},
                                                            {"end", c.segregation_end},
                                                            {"mean", c.segregation_mean}})
      << ",\n";
  // What separates the two ways fines can act on the large particles: the gas they see
  // (interstitial velocity, porosity, gas force per weight) and the collision impulse they receive
  // per second from each species, per weight.
  if (c.tagged.bodies > 0) j << "    \"tagged_bodies\": " << tagged_json(c.tagged) << ",\n";
  if (c.has_profiles) j << "    \"profiles\": " << profiles_json(profiles_, c.profiles) << ",\n";
  if (!c.plugs.empty()) j << "    \"plugs\": " << plugs_json(plugs_, c.plugs) << ",\n";
  if (c.has_bed) j << "    \"bed\": " << bed_json(bed_, c.bed) << ",\n";
  j << "    \"mechanism\": {";
  std::vector<std::pair<std::string, double>> mechanism;
  for (std::size_t s = 0; s < S; ++s) {
    const std::string& name = system.species[s].name;
    if (c.gas) {
      mechanism.emplace_back("gas_velocity_seen_" + name, c.gas_velocity[s][vertical_]);
      mechanism.emplace_back("porosity_seen_" + name, c.porosity[s]);
      mechanism.emplace_back("gas_force_per_weight_" + name,
                             c.weight[s] > 0 ? c.gas_force[s][vertical_] / c.weight[s] : NAN);
    }
  }
  for (const auto& [name, value] : impulse)
    mechanism.emplace_back("impulse_per_weight_" + name, value);
  const std::string mech = object(mechanism);
  j << mech.substr(1, mech.size() - 2) << "}\n";
  j << "  }";
  return j.str();
}

std::string RunAnalysis::impacts_report(const System& system, const Conclusions& c) const {
  const std::size_t S = system.species.size();
  std::ostringstream r;
  r << "Impacts: the collisions whose normal approach speed exceeds the impact speed v* = "
    << fixed(system.impact_speed)
    << " m/s, counted the same way by every method. Slower collisions are the chatter of lasting "
       "contacts, which a hard-sphere method counts one by one, more of them the shorter its TC "
       "time, and a soft-sphere method counts once; the impacts leave that chatter out "
       "(scenarios/guides/granular_gases.md, \"Impacts\"). Kinetic theory for impacts: nu_st times "
       "exp(-v*^2 / (2 (theta_s + theta_t))) in each cell.\n\n"
       "| pair | impacts (1/s) | kinetic theory, impacts (1/s) | ratio | impacts / collisions "
       "|\n|---|---|---|---|---|\n";
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t t = 0; t < S; ++t) {
      const std::size_t k = s * S + t;
      r << "| " << pair_name(system, s, t) << " | " << fixed(c.impact_rate[k]) << " | "
        << fixed(c.kinetic_impact_rate[k]) << " | " << fixed(c.impact_rate[k] / c.kinetic_impact_rate[k])
        << " | " << fixed(c.impact_rate[k] / c.measured_rate[k]) << " |\n";
    }
  for (std::size_t s = 0; s < S; ++s)
    r << "| " << system.species[s].name << " with walls | " << fixed(c.wall_impact_rate[s]) << " | | | "
      << fixed(c.wall_impact_rate[s] / c.wall_rate[s]) << " |\n";
  return r.str();
}

std::string RunAnalysis::report(const CollisionMethod& sim) const {
  const Conclusions c = conclude(sim);
  const System& system = sim.system();
  const std::size_t S = system.species.size();
  std::ostringstream r;
  r << "# " << scene_.name << ": run report\n\n";
  if (!scene_.description.empty()) r << scene_.description << "\n\n";
  r << "Simulated from t = 0 to " << fixed(c.duration) << " s; " << times_.size()
    << " samples. Particles:";
  for (std::size_t s = 0; s < S; ++s)
    r << (s ? "," : "") << " " << c.count[s] << " " << system.species[s].name
      << " (d = " << diameter_text(system.species[s].diameter) << ")";
  r << ".\n\n";
  if (c.mixing) {
    r << "## Mixing of the " << system.species[scene_.analysis.mixing_species].name
      << " particles\n\n"
      << "Tagged by height at t = 0 (lower half). Lacey index over " << mixing_grid_.cells[0]
      << " x " << mixing_grid_.cells[1] << " x " << mixing_grid_.cells[2]
      << " sample cells: " << fixed(c.lacey_start) << " at t = 0, " << fixed(c.lacey_end)
      << " at the end (0 segregated, 1 random).\n\n"
      << "| quantity | value |\n|---|---|\n"
      << "| mixing rate k, least-squares fit of M = 1 - (1 - M0) exp(-k t) from the measured M0 = "
      << fixed(c.rate.start) << " | " << fixed(c.rate.valid ? c.rate.rate : NAN) << " 1/s |\n"
      << "| time to M = 0.8, from the fit | " << fixed(c.rate.valid ? c.rate.time_to_08_fit : NAN)
      << " s |\n"
      << "| time to M = 0.8, first reached in the data | " << fixed(c.rate.time_to_08_data)
      << " s |\n"
      << "| rms residual of the fit | " << fixed(c.rate.rms_residual) << " |\n"
      << "| axial dispersion coefficient D, confined-bed fit of the whole MSD record | "
      << fixed(c.dispersion.valid ? c.dispersion.coefficient : NAN) << " m^2/s |\n"
      << "| D from the early growth MSD = 2 D t (up to t = " << fixed(c.early_dispersion.fit_end)
      << " s; biased low in a bounded bed) | "
      << fixed(c.early_dispersion.valid ? c.early_dispersion.coefficient : NAN) << " m^2/s |\n\n";
  }
  r << "## Collision frequencies (per particle, whole run)\n\n"
    << "Measured: counted exactly at the events. Kinetic theory: nu_st = n_t pi d_st^2 g_st "
       "sqrt(8 (theta_s + theta_t) / pi) in each of "
    << field_grid_.cells[0] << " x " << field_grid_.cells[1] << " x " << field_grid_.cells[2]
    << " cells from the local number densities and granular temperatures, averaged over the "
       "particles "
       "and the samples.\n\n| pair | measured (1/s) | kinetic theory (1/s) | ratio "
       "|\n|---|---|---|---|\n";
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t t = 0; t < S; ++t)
      r << "| " << pair_name(system, s, t) << " | " << fixed(c.measured_rate[s * S + t]) << " | "
        << fixed(c.kinetic_rate[s * S + t]) << " | "
        << fixed(c.measured_rate[s * S + t] / c.kinetic_rate[s * S + t]) << " |\n";
  for (std::size_t s = 0; s < S; ++s)
    r << "| " << system.species[s].name << " with walls | " << fixed(c.wall_rate[s]) << " | | |\n";
  r << "\n" << impacts_report(system, c);
  r << "\nGranular temperature (time average of the bed average, m^2/s^2):";
  for (std::size_t s = 0; s < S; ++s)
    r << " " << system.species[s].name << " " << fixed(c.temperature[s]) << ";";
  r << "\n";
  if (small_ >= 0)
    r << "Segregation index 2 (h_" << system.species[small_].name << " - h_"
      << system.species[large_].name << ") / (sum): " << fixed(c.segregation_start) << " at t = 0, "
      << fixed(c.segregation_end) << " at the end, " << fixed(c.segregation_mean)
      << " on average (positive: the small particles above).\n";
  // Mechanism: how smaller particles (fines) may act on the larger ones, through the gas and
  // through collisions. Only what applies: the gas part with a gas, the collision part with two
  // or more species, the per-weight column under gravity.
  const bool several = S >= 2;
  bool weighed = false;
  for (double w : c.weight) weighed |= w > 0;
  // Sections every run may have after the mechanism's.
  const std::string tail = tagged_report(c.tagged) +
                           (c.has_profiles ? profiles_report(profiles_, c.profiles) : "") +
                           (c.plugs.empty() ? "" : plugs_report(plugs_, c.plugs)) +
                           (c.has_bed ? bed_report(bed_, c.bed) : "") + numerical_settings_section(scene_);
  if (!several && !c.gas) return r.str() + tail;
  r << "\n## " << (several ? "Mechanism" : "Gas seen by the particles") << "\n\n";
  if (several && c.gas)
    r << "Fines can speed up the mixing of the large particles in two ways. (1) They take pore volume, so the gas "
         "flows faster between the large particles and drags them harder: compare the interstitial gas velocity, "
         "the porosity and the gas force (drag plus pressure gradient) per weight each species feels. (2) They "
         "collide with the large particles and give them momentum: compare the collision impulse per second a "
         "large particle receives from each species"
      << (weighed ? " with its weight" : "") << ".\n\n";
  else if (several)
    r << "Without a gas the species act on each other only through collisions: the collision impulse per second a "
         "particle receives from each species"
      << (weighed ? ", beside its weight," : "") << " says how strongly each one agitates it.\n\n";
  if (c.gas) {
    r << "| species | gas velocity seen (m/s, vertical) | porosity seen | gas force / weight (vertical) |\n"
         "|---|---|---|---|\n";
    for (std::size_t s = 0; s < S; ++s)
      r << "| " << system.species[s].name << " | " << fixed(c.gas_velocity[s][vertical_]) << " | "
        << fixed(c.porosity[s]) << " | " << (c.weight[s] > 0 ? fixed(c.gas_force[s][vertical_] / c.weight[s]) : "")
        << " |\n";
  }
  if (!several) return r.str() + tail;
  r << "\n| pair (receiver-giver) | collision impulse rate per particle (N) |"
    << (weighed ? " impulse rate / weight (dimensionless) |\n|---|---|---|\n" : "\n|---|---|\n");
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t t = 0; t < S; ++t) {
      r << "| " << pair_name(system, s, t) << " | " << fixed(c.impulse_rate[s * S + t]) << " |";
      if (weighed) r << " " << fixed(c.weight[s] > 0 ? c.impulse_rate[s * S + t] / c.weight[s] : NAN) << " |";
      r << "\n";
    }
  r << "\nThe impulse rate counts |J| of every collision (a gross rate: impulses in opposite directions do not "
       "cancel), so it measures agitation, not a net force. Compare runs with and without fines (a sweep) to see "
       "which of the two changes with the fines fraction.\n";
  return r.str() + tail;
}

}  // namespace carom
