#pragma once
/// The keys of summary.json and their units: the one table that says what every number in the
/// file is measured in. summary.json carries it as its "units" object (summary_units_json), and
/// scenarios/run/SUMMARY.md explains each row; tests/run/test_summary_units.cpp checks that every
/// key a run writes matches a row, so a new key needs its row here (and a line on the page).
///
/// A pattern is a dotted path whose `*` stands for one part of the path (no dot): a species
/// name, a pair "a-b", "species@wall", "species@walls", a wall name, or an array index. The
/// value of a key that holds an array of numbers (a force vector, a profile across bins, a
/// number per species) is one entry: its unit applies to every element.
///
/// Units: SI; "1" dimensionless, "count" a number of things (a mean of counts may be
/// fractional), "text" a string, "bool" true or false. Times named *_seconds, wall_seconds and
/// rates per wall second are wall-clock; every other time is simulated.
#include <cstddef>
#include <string>
#include <string_view>

namespace carom {

/// One row of the table.
struct SummaryKey {
  std::string_view pattern;  ///< Dotted path, `*` for one part of it.
  std::string_view unit;     ///< See above.
  std::string_view meaning;  ///< One line.
};

// clang-format off
inline constexpr SummaryKey kSummaryKeys[] = {
    // The run.
    {"carom_version", "text", "version of carom that wrote the file"},
    {"scene", "text", "the scene's name ([meta] name, else the file name)"},
    {"run.id", "text", "the run's identity, 16 hex digits, as in run.h5 and checkpoint.h5"},
    {"run.scene_hash", "text", "hash of the scene as run, 16 hex digits"},
    {"run.seed", "1", "the random seed"},
    {"run.method", "text", "collision method: event_driven, soft_sphere or monte_carlo"},
    {"status", "text", "how the run ended: completed, interrupted, a detector's name, stalled or failed (SUMMARY.md lists them)"},
    {"message", "text", "why the run stopped, when not completed"},
    {"start_time", "s", "simulated time at which this stretch began (0, or the checkpoint's)"},
    {"end_time", "s", "simulated time at which it ended"},
    {"wall_seconds", "s", "wall-clock time of the run loop"},
    {"particles", "count", "particles present at the end"},
    {"events", "count", "events in this stretch"},
    {"collisions", "count", "particle-particle collisions in this stretch"},
    {"events_total", "count", "events since t = 0"},
    {"collisions_total", "count", "particle-particle collisions since t = 0"},
    {"events_per_second", "1/s", "events per wall-clock second"},
    {"collisions_per_second", "1/s", "collisions per wall-clock second"},
    {"simulated_seconds_per_wall_second", "1", "simulated time over wall-clock time"},
    // Collisions.
    {"collision_rate_per_particle.*", "1/s", "collisions of one particle of a with particles of b ('a-b'), per simulated second"},
    {"enskog_rate_per_particle.*", "1/s", "the same from Enskog theory at the time-averaged temperature (null where it does not apply)"},
    {"impact_speed", "m/s", "normal approach speed above which a collision counts as an impact"},
    {"impact_rate_per_particle.*", "1/s", "impacts (collisions above the impact speed) of one particle of a with particles of b ('a-b'), per simulated second"},
    {"wall_collisions.*", "count", "collisions of species s with wall w ('s@w') in this stretch"},
    {"wall_impacts.*", "count", "impacts of species s on wall w ('s@w') in this stretch"},
    {"wall_force.*", "N", "time-averaged force of the particles on the wall, [x, y, z]"},
    // Temperature, pressure, energy.
    {"mean_temperature", "J", "time-averaged 2 E_kin / (3 N): an energy per particle, not m^2/s^2"},
    {"pressure.kinetic", "Pa", "time-averaged 2 E_kin / (3 V)"},
    {"pressure.collisional", "Pa", "collisional (virial) pressure, sum r_ij . J_ij / (3 V t)"},
    {"pressure.total", "Pa", "kinetic plus collisional"},
    {"energy.translational", "J", "translational kinetic energy at the end"},
    {"energy.rotational", "J", "rotational kinetic energy at the end"},
    {"energy.potential", "J", "gravitational potential energy at the end"},
    {"energy.elastic", "J", "elastic energy stored in soft-sphere contacts at the end"},
    {"energy.dissipated", "J", "energy dissipated by collisions since t = 0"},
    {"energy.gas_work", "J", "work done by the gas on the particles since t = 0"},
    // The collision method.
    {"method.kind", "text", "collision method: event_driven, soft_sphere or monte_carlo"},
    {"method.time_step", "s", "soft spheres: the velocity-Verlet step; Monte Carlo: the particle step"},
    {"method.shortest_contact_time", "s", "soft spheres: binary contact time that set the default step"},
    {"method.impact_speed", "m/s", "soft spheres: impact speed of the Hertz contact times"},
    {"method.steps", "count", "soft spheres: steps taken since the start"},
    {"method.neighbour_list_builds", "count", "soft spheres: Verlet-list rebuilds"},
    {"method.coordination_number", "1", "soft spheres: particle contacts per particle at the end"},
    {"method.wall_contacts", "count", "soft spheres: particle-wall contacts at the end"},
    {"method.mean_contact_duration", "s", "soft spheres: mean duration of the pair contacts that ended"},
    {"method.largest_overlap", "1", "soft spheres: largest overlap seen, over the smaller radius"},
    {"method.cell_size", "m", "Monte Carlo: smallest edge of the collision cells"},
    {"method.particles_per_cell", "count", "Monte Carlo: mean number of particles in a collision cell"},
    {"method.max_collisions_per_step", "count", "Monte Carlo: largest mean number of collisions per moving particle in one step"},
    {"method.travelling_collisions", "count", "Monte Carlo: collisions with fictitious partners"},
    {"method.thinning_bound_exceeded", "count", "Monte Carlo: trials whose relative speed exceeded its bound"},
    // The gas.
    {"gas.fluid_steps", "count", "fluid steps in this stretch"},
    {"gas.unconverged_steps", "count", "fluid steps whose SIMPLE iterations stopped at their limit"},
    {"gas.mapping_seconds", "s", "wall-clock time mapping particles to gas cells"},
    {"gas.solve_seconds", "s", "wall-clock time solving the gas"},
    {"gas.interpolation_seconds", "s", "wall-clock time interpolating the gas to the particles"},
    {"gas.event_seconds", "s", "the rest of the wall-clock time: the particles' own work"},
    // Inflows and outflows; * is the inflow's or outflow's index.
    {"flow.inflows.*.name", "text", "the inflow's name"},
    {"flow.inflows.*.set_mass_flow", "kg/s", "mass flow the scene asks for"},
    {"flow.inflows.*.mass_flow", "kg/s", "mass flow placed, measured between flow steps"},
    {"flow.inflows.*.mass_flow_resolution", "kg/s", "one particle's mass per measured span: the step of mass_flow"},
    {"flow.inflows.*.entered", "count", "particles placed in this stretch"},
    {"flow.inflows.*.waiting", "count", "particles owed but not yet placed at the end"},
    {"flow.inflows.*.blocked_steps", "count", "flow steps at which the inflow could not place what it owed"},
    {"flow.inflows.*.blocked_message", "text", "why it was blocked, if it was"},
    {"flow.outflows.*.name", "text", "the outflow's name"},
    {"flow.outflows.*.mass_flow", "kg/s", "mass flow that left"},
    {"flow.outflows.*.left", "count", "particles that left in this stretch"},
    {"flow.mean_particles_present", "count", "time-averaged number of particles present, per species"},
    // The analysis, over the whole run from t = 0.
    {"analysis.mixing.species", "text", "the species tagged by height at t = 0"},
    {"analysis.mixing.lacey_start", "1", "Lacey index at t = 0 (0 segregated, 1 random)"},
    {"analysis.mixing.lacey_end", "1", "Lacey index at the end"},
    {"analysis.mixing.rate", "1/s", "k of the fit M = 1 - (1 - M0) exp(-k t)"},
    {"analysis.mixing.fit_start", "1", "M0, the Lacey index the fit starts from"},
    {"analysis.mixing.time_to_m08_fit", "s", "when the fitted curve reaches M = 0.8"},
    {"analysis.mixing.time_to_m08", "s", "when the data first reach M = 0.8"},
    {"analysis.mixing.fit_rms", "1", "rms residual of the fit, in Lacey index"},
    {"analysis.dispersion.axial_coefficient", "m^2/s", "axial dispersion coefficient D, confined-bed fit of the whole record"},
    {"analysis.dispersion.axial_coefficient_early", "m^2/s", "D from the early growth MSD = 2 D t"},
    {"analysis.dispersion.early_fit_end", "s", "last time of the early fit"},
    {"analysis.dispersion.saturation_msd", "m^2", "mean squared displacement at which the bed saturates"},
    {"analysis.collision_frequency.*", "1/s", "measured collisions per particle per second, 'a-b' and 'a@walls'"},
    {"analysis.kinetic_theory_frequency.*", "1/s", "kinetic theory from the local densities and temperatures, 'a-b'"},
    {"analysis.impact_speed", "m/s", "normal approach speed above which a collision counts as an impact"},
    {"analysis.impact_frequency.*", "1/s", "measured impacts per particle per second, 'a-b' and 'a@walls'"},
    {"analysis.kinetic_theory_impact_frequency.*", "1/s", "kinetic theory's impacts (collisions faster than the impact speed), 'a-b'"},
    {"analysis.granular_temperature.*", "m^2/s^2", "per species, time-averaged <|v - u_local|^2> / 3"},
    {"analysis.segregation_index.start", "1", "2 (h_small - h_large) / (h_small + h_large) at t = 0"},
    {"analysis.segregation_index.end", "1", "the same at the end"},
    {"analysis.segregation_index.mean", "1", "its time average"},
    {"analysis.mechanism.gas_velocity_seen_*", "m/s", "vertical interstitial gas velocity at the species' particles"},
    {"analysis.mechanism.porosity_seen_*", "1", "porosity at the species' particles"},
    {"analysis.mechanism.gas_force_per_weight_*", "1", "vertical gas force on the species over its weight"},
    {"analysis.mechanism.impulse_per_weight_*", "1", "collision impulse per second on one particle of a from b ('a-b'), over its weight"},
    {"analysis.tagged_bodies.bodies", "count", "tagged bodies"},
    {"analysis.tagged_bodies.ids", "1", "their particle ids"},
    {"analysis.tagged_bodies.direction", "1", "unit vector of their mean velocity at the first sample"},
    {"analysis.tagged_bodies.start_speed", "m/s", "mean velocity along direction at the first sample"},
    {"analysis.tagged_bodies.end_speed", "m/s", "the same at the last sample"},
    {"analysis.tagged_bodies.mean_force", "N", "mean collision force on one body over the record, [x, y, z]"},
    {"analysis.tagged_bodies.mean_force_along_direction", "N", "its component along direction (negative: drag)"},
    {"analysis.tagged_bodies.inverse_speed_fit.valid", "bool", "whether the fit 1/V = 1/V0 + k t was made"},
    {"analysis.tagged_bodies.inverse_speed_fit.k", "1/m", "k of the fit"},
    {"analysis.tagged_bodies.inverse_speed_fit.k_error", "1/m", "its standard error"},
    {"analysis.tagged_bodies.inverse_speed_fit.intercept", "s/m", "1/V0 of the fit"},
    {"analysis.tagged_bodies.inverse_speed_fit.intercept_error", "s/m", "its standard error"},
    {"analysis.tagged_bodies.inverse_speed_fit.points", "count", "samples fitted"},
    {"analysis.profiles.axis", "text", "bin axis across the sections: x, y or z"},
    {"analysis.profiles.vertical", "text", "axis of the section heights"},
    {"analysis.profiles.thickness", "m", "section thickness"},
    {"analysis.profiles.start", "s", "samples before this time are left out"},
    {"analysis.profiles.samples", "count", "samples averaged"},
    {"analysis.profiles.first", "s", "time of the first sample averaged"},
    {"analysis.profiles.last", "s", "time of the last sample averaged"},
    {"analysis.profiles.bin_centres", "m", "bin centres along the bin axis"},
    {"analysis.profiles.sections.*.height", "m", "section centre"},
    {"analysis.profiles.sections.*.solid_fraction", "1", "per bin"},
    {"analysis.profiles.sections.*.particles_per_sample", "count", "mean particles per sample, per bin"},
    {"analysis.profiles.sections.*.mean_velocity", "m/s", "per bin, [x, y, z]"},
    {"analysis.profiles.sections.*.std_velocity", "m/s", "standard deviation of the velocities, per bin, [x, y, z]"},
    {"analysis.profiles.sections.*.mean_spin", "rad/s", "per bin, [x, y, z]"},
    {"analysis.plugs.bin", "m", "bin length of the axial profile"},
    {"analysis.plugs.bottom", "m", "lower end of the profile"},
    {"analysis.plugs.area", "m^2", "cross-section open to the particles"},
    {"analysis.plugs.diameter", "m", "largest particle diameter d, the unit of plug lengths"},
    {"analysis.plugs.min_bins", "count", "shortest plug, bins"},
    {"analysis.plugs.by_threshold.*.threshold", "1", "solid fraction at or above which a bin is in a plug"},
    {"analysis.plugs.by_threshold.*.plugs_mean", "count", "mean plugs per sample"},
    {"analysis.plugs.by_threshold.*.plugs_std", "count", "their standard deviation"},
    {"analysis.plugs.by_threshold.*.length_mean", "1", "mean plug length over d"},
    {"analysis.plugs.by_threshold.*.length_std", "1", "its standard deviation"},
    {"analysis.plugs.by_threshold.*.plugs_counted", "count", "plugs over all samples"},
    {"analysis.plugs.by_threshold.*.bed_top_mean", "m", "mean top of the highest plug"},
    {"analysis.plugs.by_threshold.*.rise_speed", "m/s", "mean rising speed of the bed top"},
    {"analysis.plugs.by_threshold.*.fall_speed", "m/s", "mean falling speed of the bed top"},
    {"analysis.plugs.by_threshold.*.exchange", "1", "share of particles that changed plugs"},
    {"analysis.plugs.by_threshold.*.travel_1s", "m", "mean |z(t + 1 s) - z(t)|"},
    {"analysis.bed.start", "s", "samples before this time are left out"},
    {"analysis.bed.samples", "count", "samples concluded from"},
    {"analysis.bed.first", "s", "time of the first sample concluded from"},
    {"analysis.bed.last", "s", "time of the last"},
    {"analysis.bed.interval", "s", "mean interval between those samples"},
    {"analysis.bed.vertical", "text", "the vertical axis: x, y or z"},
    {"analysis.bed.floor", "m", "the domain's floor, from which heights are measured"},
    {"analysis.bed.bin", "m", "bin thickness of the solid-fraction profile"},
    {"analysis.bed.threshold", "1", "solid fraction that marks the bed surface"},
    {"analysis.bed.heights.*.definition", "text", "share (of the beads' tops below) or solid_fraction (the surface)"},
    {"analysis.bed.heights.*.share", "1", "share of the beads whose tops lie below the height"},
    {"analysis.bed.heights.*.threshold", "1", "solid fraction below which the surface lies"},
    {"analysis.bed.heights.*.mean", "m", "mean bed height above the floor"},
    {"analysis.bed.heights.*.std", "m", "its standard deviation over the samples"},
    {"analysis.bed.heights.*.min", "m", "its minimum"},
    {"analysis.bed.heights.*.max", "m", "its maximum"},
    {"analysis.bed.pressure.drop_mean", "Pa", "mean gas pressure drop over the domain"},
    {"analysis.bed.pressure.drop_std", "Pa", "its standard deviation"},
    {"analysis.bed.pressure.gas_column", "Pa", "the gas column's own weight per area, rho_g g H"},
    {"analysis.bed.pressure.momentum_inflow", "Pa", "mean net gas momentum inflow per area"},
    {"analysis.bed.pressure.bed_drop", "Pa", "the part that carries the bed: drop - rho_g g H + inflow"},
    {"analysis.bed.pressure.buoyant_weight_per_area", "Pa", "mean sum (rho_p - rho_g) g V / A"},
    {"analysis.bed.pressure.bed_drop_over_weight", "1", "bed_drop over buoyant_weight_per_area"},
    {"analysis.bed.probes.*.point", "m", "probe point [x, y, z]"},
    {"analysis.bed.probes.*.height", "m", "probe height above the floor (cross-section mean)"},
    {"analysis.bed.probes.*.mean", "Pa", "mean gas pressure"},
    {"analysis.bed.probes.*.std", "Pa", "standard deviation of its fluctuations"},
    {"analysis.bed.probes.*.dominant_frequency", "1/s", "frequency (Hz) of the largest spectral amplitude"},
    {"analysis.bed.probes.*.dominant_amplitude", "Pa", "that amplitude"},
    {"analysis.bed.probes.*.samples", "count", "evenly spaced samples of the spectrum"},
    {"analysis.bed.probes.*.resolution", "1/s", "frequency resolution 1/T"},
    {"analysis.bed.probes.*.nyquist", "1/s", "highest frequency 1/(2 dt)"},
    {"analysis.bed.map.axis", "text", "axis across the maps"},
    {"analysis.bed.map.bins", "count", "bins across and up"},
    {"analysis.bed.map.slab_centre", "m", "centre of the maps' slab along the third axis"},
    {"analysis.bed.map.slab_thickness", "m", "its thickness"},
    {"analysis.bed.map.largest_upward_flux", "kg/m^2/s", "largest time-averaged upward solids mass flux of a bin"},
    {"analysis.bed.map.largest_downward_flux", "kg/m^2/s", "smallest (most downward) of them"},
};
// clang-format on

/// True when the dotted `path` matches `pattern`: equal, with each `*` taking one or more
/// characters other than '.'.
inline bool summary_pattern_matches(std::string_view pattern, std::string_view path) {
  if (pattern.empty()) return path.empty();
  if (pattern.front() != '*')
    return !path.empty() && path.front() == pattern.front() &&
           summary_pattern_matches(pattern.substr(1), path.substr(1));
  for (std::size_t k = 1; k <= path.size() && path[k - 1] != '.'; ++k)
    if (summary_pattern_matches(pattern.substr(1), path.substr(k))) return true;
  return false;
}

/// The row whose pattern matches `path`, or nullptr.
inline const SummaryKey* summary_key_for(std::string_view path) {
  for (const SummaryKey& key : kSummaryKeys)
    if (summary_pattern_matches(key.pattern, path)) return &key;
  return nullptr;
}

/// The table as summary.json's "units" object: {"pattern": "unit", ...}, one row a line,
/// indented as a key of the file's top-level object.
inline std::string summary_units_json() {
  std::string out = "{";
  bool first = true;
  for (const SummaryKey& key : kSummaryKeys) {
    out += first ? "\n    \"" : ",\n    \"";
    out += key.pattern;
    out += "\": \"";
    out += key.unit;
    out += "\"";
    first = false;
  }
  return out + "\n  }";
}

}  // namespace carom
