#include "scenarios/cli/recommend.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>
#include <utility>

#include "core/contact_value.hpp"
#include "core/display_number.hpp"
#include "events/soft_sphere/contact_model.hpp"
#include "fluid/drag.hpp"
#include "scenarios/analysis/chart_evidence.hpp"

namespace carom {

namespace {

/// A number for the report (core/display_number.hpp: as typed, else 4 significant digits).
std::string num(double x) { return display_number(x); }

/// Carnahan-Starling contact value, the packing capped at 0.6 (a frozen packing has no mean free
/// time to speak of; the cap keeps the estimate finite).
double capped_contact_value(double phi) { return carnahan_starling_contact_value(std::min(phi, 0.6)); }

/// The elastic Hertz contact of two equal spheres of the species: the soft-sphere method's own
/// (events/soft_sphere/contact_model.hpp), whose peak_overlap(v) and contact_time(v) give the
/// undamped impact at approach speed v.
PairContact hertz_pair(const Species& s, const ElasticMaterial& m) {
  return make_pair_contact(s.radius(), s.mass(), m, s.radius(), s.mass(), m, 1.0, 0.0, SoftSphereOptions{});
}

/// The solid fraction around a typical particle: the domain cut into cells of about `edge`
/// (whole cells, at least one per axis), and for each particle the solid volume of the OTHER
/// particles in its cell over the cell's volume, averaged over the particles. Leaving the
/// particle itself out makes it unbiased for a uniform random placement (a Poisson count N has
/// E[N (N - 1)] = <N>^2), where counting it raised a dilute gas's estimate by 1 + 1/<N>. Only
/// the occupied cells are visited (the particles sorted by cell).
double solid_fraction_around_particles(const System& system, double edge) {
  const ParticleStore& p = system.particles;
  const Domain& domain = system.domain;
  std::array<double, 3> size{};
  for (int k = 0; k < 3; ++k) {
    const double cells = std::max(1.0, std::floor(domain.length()[k] / edge));
    size[k] = domain.length()[k] / cells;
  }
  using Cell = std::array<std::int64_t, 3>;
  std::vector<std::pair<Cell, std::size_t>> order(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    Cell c{};
    for (int k = 0; k < 3; ++k)
      c[k] = static_cast<std::int64_t>(std::floor((p.position[i][k] - domain.lower[k]) / size[k]));
    order[i] = {c, i};
  }
  std::sort(order.begin(), order.end());
  const double volume = size[0] * size[1] * size[2];
  double weighted = 0.0;
  for (std::size_t begin = 0; begin < order.size();) {
    std::size_t end = begin;
    double solid = 0.0;
    for (; end < order.size() && order[end].first == order[begin].first; ++end)
      solid += system.species[p.species[order[end].second]].volume();
    weighted += static_cast<double>(end - begin - 1) * solid / volume;
    begin = end;
  }
  return weighted / static_cast<double>(p.size());
}

/// "[chart FILE, measured DATE]": where a recommendation's numbers come from.
std::string cite(const evidence::ChartSource& chart) {
  return std::string(" [chart ") + chart.file + ", measured " + chart.date + "]";
}

/// Percent, formatted as num().
std::string pct(double x) {
  return num(100.0 * x) + " %";
}

/// The Monte Carlo method's contact value for the scene's solid fraction, from the Monte Carlo
/// map: the Enskog contact value where Boltzmann's rate leaves the map's tolerance, and the
/// event-driven method where even the Enskog rate leaves it.
Advice monte_carlo_advice(const Scene& scene, const SceneNumbers& n) {
  const bool enskog = scene.method.monte_carlo.contact_value == ContactValue::Enskog;
  Advice a{"monte carlo", "", "", "", false};
  a.scene = std::string("contact_value = ") + (enskog ? "enskog" : "none");
  const double phi = std::max(n.solid_fraction, n.solid_fraction_seen);
  const std::string tolerance = pct(evidence::kMonteCarloTolerance);
  if (phi > evidence::kMonteCarloEnskogLimit) {
    a.choice = "event_driven";
    a.reason = "solid fraction " + num(phi) + " > " + num(evidence::kMonteCarloEnskogLimit) +
               ": beyond it even the Enskog collision frequency of the Monte Carlo model left the "
               "exact one by more than " +
               tolerance + cite(evidence::kMonteCarloMap);
    a.differs = true;
    return a;
  }
  const bool need_enskog = phi > evidence::kMonteCarloPlainLimit;
  a.choice = need_enskog ? "contact_value = enskog" : "contact_value = none or enskog";
  a.reason = "solid fraction " + num(phi) +
             ": on the Monte Carlo map (2000 elastic spheres) the collision frequency left the "
             "exact one by more than " +
             tolerance + " from phi = " + num(evidence::kMonteCarloPlainLimit) +
             " with contact_value = none (" + pct(evidence::kMonteCarloPlainErrorAt005) +
             " at phi = 0.05) and stayed within " + pct(evidence::kMonteCarloEnskogWorstError) +
             " up to phi = " + num(evidence::kMonteCarloEnskogLimit) +
             " with enskog; the mean temperature stayed within " +
             pct(evidence::kMonteCarloTemperatureWorstError) +
             " up to phi = " + num(evidence::kMonteCarloTemperatureLimit) +
             " with either partner, and was " + pct(evidence::kMonteCarloCellParticleErrorAt02) +
             " off at phi = 0.2 (cell_particle), " + pct(evidence::kMonteCarloGaussianErrorAt03) +
             " at phi = 0.3 (gaussian)" + cite(evidence::kMonteCarloMap);
  a.differs = need_enskog && !enskog;
  return a;
}

}  // namespace

SceneNumbers scene_numbers(const Scene& scene, bool settling_skipped) {
  const System& system = scene.system;
  const ParticleStore& p = system.particles;
  const Domain& domain = system.domain;
  const std::size_t S = system.species.size();
  const Vec3& gravity = system.flight.gravity;
  const double g = gravity.norm();
  const int up = system.flight.vertical_axis();
  SceneNumbers n;

  // Masses, solid fraction, the largest and the Sauter-mean diameter.
  std::vector<double> mass(S, 0.0);
  double solid = 0.0, total_mass = 0.0, d_max = 0.0, d3 = 0.0, d2 = 0.0, v2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Species& s = system.species[p.species[i]];
    mass[p.species[i]] += s.mass();
    total_mass += s.mass();
    solid += s.volume();
    d_max = std::max(d_max, s.diameter);
    d3 += std::pow(s.diameter, 3);
    d2 += s.diameter * s.diameter;
    v2 += p.velocity[i].squaredNorm();
  }
  n.solid_fraction = solid / domain.volume();
  const double sauter = d2 > 0 ? d3 / d2 : 0.0;
  if (p.size() > 0) n.solid_fraction_seen = solid_fraction_around_particles(system, 4.0 * d_max);
  n.packing_source = "around a typical particle as placed (sample cells of 4 diameters)";
  if (settling_skipped && g > 0 && n.solid_fraction_seen < kSettledPacking) {
    n.solid_fraction_seen = kSettledPacking;
    n.packing_source = "of a settled random packing (the settling run is not run by check)";
  }

  // The gas: inlet velocity, relaxation times, Stokes numbers, U_mf.
  const GasSettings& gas = scene.gas;
  const bool has_gas = gas.coupling != CouplingLevel::None;
  int inlet_axis = up;
  for (int side = 0; side < 6; ++side)
    if (gas.sides[side].kind == GasSide::Kind::Inlet &&
        gas.sides[side].velocity > n.inlet_velocity) {
      n.inlet_velocity = gas.sides[side].velocity;
      inlet_axis = side / 2;
    }
  if (!has_gas) n.inlet_velocity = 0.0;
  const DragClosure closure(gas.closure, gas.fluidization_porosity, g > 0 ? g : 9.81);
  double tau_min = INFINITY;
  for (std::size_t s = 0; s < S; ++s) {
    const Species& sp = system.species[s];
    SpeciesNumbers x;
    x.name = sp.name;
    x.mass_share = total_mass > 0 ? mass[s] / total_mass : 0.0;
    if (has_gas) {
      DragInput in;
      in.diameter = in.sauter_diameter = sp.diameter;
      in.gas_density = gas.density;
      in.gas_viscosity = gas.viscosity;
      in.particle_density = sp.density;
      x.relaxation_time = g > 0 ? closure.terminal_velocity(in) / g
                                : sp.density * sp.diameter * sp.diameter / (18.0 * gas.viscosity);
      if (n.inlet_velocity > 0)
        x.stokes = x.relaxation_time * n.inlet_velocity / domain.length()[inlet_axis];
      if (g > 0) x.minimum_fluidization = closure.minimum_fluidization_velocity(in, 0.4);
      if (mass[s] > 0) tau_min = std::min(tau_min, x.relaxation_time);
    }
    n.species.push_back(x);
  }
  if (has_gas) {
    n.mass_loading = total_mass / (gas.density * (domain.volume() - solid));
    if (std::isfinite(tau_min)) n.step_ratio = tau_min / gas.time_step;
    n.cell_ratio = INFINITY;
    n.gas_dimensions = 1;
    n.gas_dimensions_needed = 1;
    for (int k = 0; k < 3; ++k) {
      const double edge = domain.length()[k] / gas.cells[k];
      if (gas.cells[k] > 1) n.cell_ratio = std::min(n.cell_ratio, edge / d_max);
      if (k == up) continue;
      if (gas.cells[k] > 1) ++n.gas_dimensions;
      if (domain.length()[k] > 2.0 * kCellDiameters * d_max * (1.0 + 1e-9))
        ++n.gas_dimensions_needed;
    }
    if (!std::isfinite(n.cell_ratio)) n.cell_ratio = NAN;
  }

  // Tube: a cylinder wall, or the narrowest lateral extent of the box.
  for (const Wall& w : system.walls)
    if (const auto* c = std::get_if<CylinderWall>(&w.shape)) {
      n.tube = true;
      n.tube_ratio = d_max > 0 ? 2.0 * c->radius / d_max : NAN;
      // A tube's gas is resolved across it only if the tube holds 2 cells of 3 diameters.
      if (has_gas && !(n.tube_ratio > 2.0 * kCellDiameters * (1.0 + 1e-9)))
        n.gas_dimensions_needed = 1;
    }
  if (!n.tube && d_max > 0) {
    n.tube_ratio = INFINITY;
    for (int k = 0; k < 3; ++k)
      if (k != up) n.tube_ratio = std::min(n.tube_ratio, domain.length()[k] / d_max);
  }

  // Collision speeds: the initial motion, else the gas, else a fall through the domain.
  const double rms = p.size() > 0 ? std::sqrt(v2 / static_cast<double>(p.size())) : 0.0;
  if (rms > 0) {
    n.speed = rms;
    n.speed_source = "the initial rms speed";
  } else if (n.inlet_velocity > 0) {
    n.speed = n.inlet_velocity;
    n.speed_source = "the superficial gas velocity; bubbles stir beads at a fraction of it";
  } else if (g > 0) {
    n.speed = std::sqrt(2.0 * g * domain.length()[up]);
    n.speed_source = "a fall through the domain's height";
  }
  if (sauter > 0 && n.speed > 0 && n.solid_fraction_seen > 0) {
    // Enskog, omega = 4 n d^2 g0 sqrt(pi T / m) with T = m v^2 / 3.
    const double number_density =
        6.0 * n.solid_fraction_seen / (std::numbers::pi * std::pow(sauter, 3));
    const double omega = 4.0 * number_density * sauter * sauter *
                         capped_contact_value(n.solid_fraction_seen) * std::sqrt(std::numbers::pi / 3.0) *
                         n.speed;
    n.mean_free_time = 1.0 / omega;
  }

  // Contact time: Hertz with the scene's elastic constants, else the TC model's.
  const auto& materials = scene.method.soft_sphere.species_materials;
  std::size_t largest = 0;
  for (std::size_t s = 1; s < S; ++s)
    if (system.species[s].diameter > system.species[largest].diameter) largest = s;
  // (The TC model's contact_time is a numerical remedy, not the beads' contact: not used.)
  if (largest < materials.size() && materials[largest].young_modulus > 0 && n.speed > 0) {
    const PairContact hertz = hertz_pair(system.species[largest], materials[largest]);
    n.contact_time = hertz.contact_time(n.speed);
    n.peak_overlap = hertz.peak_overlap(n.speed) / system.species[largest].radius();
    n.contact_source = "Hertz for two " + system.species[largest].name + " at the speed scale, from young_modulus = " +
                       num(materials[largest].young_modulus) + " Pa";
    n.young_modulus = materials[largest].young_modulus;
  } else {
    n.contact_source = "give young_modulus in [[species]] to estimate it";
  }

  // Lasting contacts.
  bool dissipative = false, floor = false;
  for (std::size_t s = 0; s < S; ++s) {
    for (std::size_t t = 0; t < S; ++t) dissipative |= system.materials.pair(s, t).restitution < 1;
    for (std::size_t w = 0; w < system.walls.size(); ++w)
      dissipative |= system.materials.wall(s, w).restitution < 1;
  }
  floor = g > 0 && !domain.periodic[up];
  // The time to land: the domain's height at the terminal velocity (with a gas) or in free fall.
  double fall = g > 0 ? std::sqrt(2.0 * domain.length()[up] / g) : INFINITY;
  for (const SpeciesNumbers& x : n.species)
    if (std::isfinite(x.relaxation_time) && x.relaxation_time > 0)
      fall = std::max(fall, domain.length()[up] / (x.relaxation_time * g));
  double moving = 0.0;  // mass share of the species that move (fixed ones never do)
  for (std::size_t s = 0; s < S; ++s)
    if (!system.species[s].fixed) moving += n.species[s].mass_share;
  if (moving == 0.0) {
    n.lasting_reason = system.particles.size() == 0
                           ? "no particles at t = 0: inflows bring them later, and these "
                             "estimates from t = 0 say nothing about those"
                           : "every particle is fixed";
  } else if (has_gas && n.inlet_velocity > 0 && g > 0) {
    for (std::size_t s = 0; s < S; ++s)
      if (!system.species[s].fixed && n.inlet_velocity <= n.species[s].minimum_fluidization)
        n.lasting_share += n.species[s].mass_share;
    n.lasting_reason = n.lasting_share > 0 ? "species with U <= U_mf stay packed"
                                           : "every species is fluidized: U > U_mf";
  } else if (floor && dissipative && scene.end_time > fall) {
    n.lasting_share = moving;
    n.lasting_reason =
        "dissipative particles under gravity with nothing to lift them come to rest on the floor "
        "(they land within about " +
        num(fall) + " s)";
  } else if (floor && dissipative) {
    n.lasting_reason = "the run ends (t = " + num(scene.end_time) +
                       " s) before the particles land (about " + num(fall) + " s)";
  } else {
    n.lasting_reason =
        g > 0 ? "elastic or without a floor: nothing comes to rest" : "no gravity: a granular gas";
  }
  return n;
}

/// The soft-sphere step and stiffness, from the soft-step and stiffness-against-load maps.
std::vector<Advice> soft_sphere_advice(const Scene& scene, const SceneNumbers& n) {
  const SoftSphereOptions& o = scene.method.soft_sphere;
  std::vector<Advice> advice;
  // The step in contact times: the scene's fraction, or its fixed step over the estimate.
  const double fraction = o.time_step > 0 ? o.time_step / n.contact_time : o.step_fraction;
  Advice step{"soft-sphere step", "", "", "", false};
  step.scene = o.time_step > 0 ? "time_step = " + num(o.time_step) + " s"
                               : "step_fraction = " + num(o.step_fraction);
  const std::string map =
      "the soft-step map completed every step up to " + num(evidence::kSoftStepLargestCompleted) +
      " of the contact time and stopped every one from " + num(evidence::kSoftStepFirstStopped) +
      "; the peak overlap was " + num(evidence::kSoftStepOverlapDefault) + " R at 1/50 of it and " +
      num(evidence::kSoftStepOverlapAt04) + " R at 0.4" + cite(evidence::kSoftStepMap);
  if (!std::isfinite(fraction)) {
    step.choice = "step_fraction = " + num(o.step_fraction);
    step.reason =
        "the contact time is unknown here (give young_modulus), so a fixed time_step "
        "cannot be judged; " +
        map;
    step.differs = o.time_step > 0;
  } else if (fraction > evidence::kSoftStepLargestCompleted) {
    step.choice = "step_fraction = " + num(SoftSphereOptions{}.step_fraction);
    step.reason = "the step is " + num(fraction) + " of the contact time: " + map;
    step.differs = true;
  } else {
    step.choice = step.scene;
    step.reason = "the step is " + num(fraction) + " of the contact time, within the stable " +
                  "range: " + map;
  }
  advice.push_back(step);

  Advice stiff{"soft-sphere stiffness", "", "", "", false};
  stiff.scene = "max_overlap = " + num(o.max_overlap);
  const std::string load =
      "; on the stiffness-against-load map the overlap detector's "
      "boundary followed the Hertz impact estimate (at g = 9.81 m/s^2 it "
      "stopped " +
      num(evidence::kSoftLoadStopped) + " Pa and completed " + num(evidence::kSoftLoadCompleted) +
      " Pa, the estimate " + num(evidence::kSoftLoadHertzEstimate) + " Pa)" +
      cite(evidence::kSoftLoadMap);
  if (!std::isfinite(n.peak_overlap)) {
    stiff.choice = stiff.scene;
    stiff.reason = "no Hertz estimate without young_modulus" + load;
  } else if (n.peak_overlap > o.max_overlap) {
    // Hertz: delta_max ~ E^(-2/5), so the modulus that brings it to max_overlap.
    stiff.choice = "young_modulus about " + num(std::pow(n.peak_overlap / o.max_overlap, 2.5)) +
                   " times stiffer";
    stiff.reason = "a binary impact at the speed scale overlaps " + num(n.peak_overlap) +
                   " R (Hertz), beyond max_overlap: the overlap detector will stop the run" + load;
    stiff.differs = true;
  } else {
    stiff.choice = stiff.scene;
    stiff.reason = "a binary impact at the speed scale overlaps " + num(n.peak_overlap) +
                   " R (Hertz), within max_overlap" + load;
  }
  advice.push_back(stiff);
  return advice;
}

std::vector<Advice> recommend(const Scene& scene, const SceneNumbers& n) {
  std::vector<Advice> advice;
  const bool has_gas = scene.gas.coupling != CouplingLevel::None;
  const MethodKind now = scene.method.kind;

  // Method.
  Advice method{"method", "event_driven", "", std::string(method_name(now)), false};
  const double share = n.contact_time / n.mean_free_time;
  if (n.lasting_share >= kLastingShare) {
    method.choice = "soft_sphere";
    method.reason =
        num(100 * n.lasting_share) + " % of the mass in lasting contacts (" + n.lasting_reason +
        "): hard spheres would need the TC model, which makes those contacts smooth and elastic";
  } else if (std::isfinite(share) && share > kContactShare) {
    method.choice = "soft_sphere";
    // Hertz: t_c ~ E^(-2/5), so the modulus from which the contacts would be binary.
    const double binary_from = n.young_modulus * std::pow(share / kContactShare, 2.5);
    method.reason = "contacts last " + num(share) + " of the mean free time (> " +
                    num(kContactShare) + "): collisions are not binary. This rests on young_modulus = " +
                    num(n.young_modulus) + " Pa of [[species]], read for soft spheres: a modulus "
                    "softened for a cheaper soft-sphere step lengthens the contacts, and with the "
                    "material's own modulus above " + num(binary_from) +
                    " Pa they would be binary and exact events would do (without young_modulus, "
                    "carom check does not judge contacts)";
  } else {
    method.reason =
        "binary collisions (" +
        (std::isfinite(share) ? "contact time " + num(share) + " of the mean free time"
                              : std::string("contact time unknown")) +
        ", " + num(100 * n.lasting_share) +
        " % in lasting contacts): exact events. Monte Carlo is not recommended by itself: "
        "on the dilute gas chart (1320 spheres, phi = 0.05) it cost " +
        num(evidence::kDiluteGasMonteCarloCostLow) + "-" +
        num(evidence::kDiluteGasMonteCarloCostHigh) + " times the events (" +
        num(evidence::kDiluteGasEventCost) +
        " CPU s per simulated s) and missed the collision "
        "frequency by " +
        pct(evidence::kDiluteGasMonteCarloErrorLow) + " to " +
        pct(evidence::kDiluteGasMonteCarloErrorHigh) + "; soft spheres came within " +
        pct(evidence::kDiluteGasSoftErrorHigh) + " at " + num(evidence::kDiluteGasSoftCostLow) +
        "-" + num(evidence::kDiluteGasSoftCostHigh) + " times the cost" +
        cite(evidence::kDiluteGas);
  }
  method.differs = method.choice != method.scene;
  advice.push_back(method);
  if (now == MethodKind::MonteCarlo) advice.push_back(monte_carlo_advice(scene, n));
  if (now == MethodKind::SoftSphere || method.choice == "soft_sphere")
    for (Advice& a : soft_sphere_advice(scene, n)) advice.push_back(std::move(a));
  if (!has_gas) {
    advice.push_back({"coupling", "none", "no gas in the scene", "none", false});
    return advice;
  }

  // Coupling.
  double stokes_min = INFINITY;
  for (const SpeciesNumbers& x : n.species)
    if (x.mass_share > 0 && std::isfinite(x.stokes)) stokes_min = std::min(stokes_min, x.stokes);
  const CouplingLevel level = scene.gas.coupling;
  Advice coupling{"coupling", "two-way", "", level == CouplingLevel::OneWay ? "one-way" : "two-way",
                  false};
  if (std::isfinite(stokes_min) && stokes_min > kNoGasStokes) {
    coupling.choice = "none";
    coupling.reason = "Stokes number " + num(stokes_min) + " > " + num(kNoGasStokes) +
                      ": the gas changes the particles' velocities by about 1/St per flow time";
  } else if (n.mass_loading < kOneWayLoading) {
    coupling.choice = "one-way";
    coupling.reason = "mass loading " + num(n.mass_loading) + " < " + num(kOneWayLoading) +
                      ": the particles change the gas momentum by about that share";
  } else {
    coupling.reason = "mass loading " + num(n.mass_loading) + " >= " + num(kOneWayLoading) +
                      ": the particles' drag and volume change the gas (a small fluidized bed "
                      "with one-way coupling carried only " +
                      num(evidence::kFluidOneWayForceLow) + "-" +
                      num(evidence::kFluidOneWayForceHigh) +
                      " of its weight on the gas, stayed packed and stopped with "
                      "lasting_contacts)" +
                      cite(evidence::kFluidMap);
  }
  coupling.differs = coupling.choice != coupling.scene;
  advice.push_back(coupling);

  // Flight (event-driven and Monte Carlo flights between the gas steps).
  if (method.choice != "soft_sphere") {
    const bool kick = scene.flight.model == FlightModel::Kick;
    Advice flight{"flight", "relax", "", kick ? "kick" : "relax", false};
    // What the fluid step itself costs in accuracy, with relax flights, on the fluid map.
    const std::string fluid_step =
        ". With relax flights, fluid steps from 1e-4 s to " + num(evidence::kFluidLargestStep) +
        " s moved a small fluidized bed's gas force per weight by at most " +
        pct(evidence::kFluidStepForceError) + " and its mixing rate by at most " +
        pct(evidence::kFluidStepMixingError) + cite(evidence::kFluidMap);
    // The kick map: a first-order error of about kKickErrorPerStep dt_p / tau, and instability
    // from kKickLimitLow-High of 2 tau (the refreshed drag's slope, not 2 tau itself).
    const std::string kick_map =
        "; on the kick map the fall's error was about " + num(evidence::kKickErrorPerStep) +
        " step / tau, and the largest stable step " + num(evidence::kKickLimitLow) + "-" +
        num(evidence::kKickLimitHigh) + " of 2 tau" + cite(evidence::kKickMap);
    const double kick_error = evidence::kKickErrorPerStep / n.step_ratio;
    if (n.step_ratio >= kKickStepRatio) {
      flight.choice = "kick or relax";
      flight.reason = "the shortest relaxation time is " + num(n.step_ratio) +
                      " fluid steps: kicks are stable, first-order accurate to about " +
                      pct(kick_error) + ", and cheaper to predict" + kick_map + fluid_step;
    } else {
      const bool unstable = n.step_ratio < 1.0 / (2.0 * evidence::kKickLimitLow);
      flight.reason = "the shortest relaxation time is " + num(n.step_ratio) + " fluid steps (< " +
                      num(kKickStepRatio) + "): kicks at the fluid step would be " +
                      (unstable ? "unstable" : "off by about " + pct(kick_error)) + kick_map +
                      "; relax flights are exact for any step" + fluid_step;
      flight.differs = kick;
    }
    advice.push_back(flight);
  }

  // Gas grid.
  const char* names[] = {"", "1-D (cells along the flow only)", "2-D", "3-D"};
  const bool at_rest = n.inlet_velocity == 0 && coupling.choice != "two-way";
  const int needed = at_rest ? 1 : n.gas_dimensions_needed;
  Advice grid{"gas grid", names[needed], "", names[n.gas_dimensions], false};
  if (at_rest) {
    grid.reason = "no inlet and the particles do not move the gas: it stays uniform";
  } else {
    grid.reason = std::string("an axis is resolved where it holds 2 cells of ") + num(kCellDiameters) +
                  " largest diameters; " + (n.tube ? "the tube is " : "the narrowest lateral extent is ") +
                  num(n.tube_ratio) + " diameters. The cell size itself is the scene's choice (" +
                  num(n.cell_ratio) +
                  " diameters here; the shipped beds use 2 to 4): in a small fluidized bed, cells of 2 "
                  "and 4 diameters moved the gas force per weight by " +
                  pct(evidence::kFluidForceErrorCell2) + " and " + pct(evidence::kFluidForceErrorCell4) +
                  " but the mixing rate by " + pct(evidence::kFluidMixingErrorCell2) + " and " +
                  pct(evidence::kFluidMixingErrorCell4) +
                  " from cells of 1 diameter, so a mixing rate is converged in the cell size only "
                  "where a chart shows it" +
                  cite(evidence::kFluidMap);
  }
  grid.differs = n.gas_dimensions != needed;
  advice.push_back(grid);
  return advice;
}

MethodKind recommended_method(const std::vector<Advice>& advice) {
  for (std::size_t k = 0; k < kMethodNames.size(); ++k)
    if (!advice.empty() && advice.front().choice == kMethodNames[k])
      return static_cast<MethodKind>(k);
  return MethodKind::EventDriven;
}

std::string describe_recommendation(const SceneNumbers& n, const std::vector<Advice>& advice) {
  std::ostringstream out;
  out << "\nthe least model this scene needs (estimates from t = 0; carom run --method auto uses "
         "the method):\n";
  out << "  solid fraction " << num(n.solid_fraction) << " of the domain, "
      << num(n.solid_fraction_seen) << " " << n.packing_source << "\n";
  if (std::isfinite(n.speed))
    out << "  speed scale " << num(n.speed) << " m/s from " << n.speed_source << "\n  mean free time "
        << num(n.mean_free_time) << " s (Enskog at that solid fraction and speed)\n";
  if (std::isfinite(n.contact_time)) {
    out << "  contact time " << num(n.contact_time) << " s (" << n.contact_source << ")";
    if (std::isfinite(n.contact_time / n.mean_free_time))
      out << ", " << num(n.contact_time / n.mean_free_time) << " of the mean free time";
    if (std::isfinite(n.peak_overlap)) out << "; peak overlap " << num(n.peak_overlap) << " of the radius";
  } else {
    out << "  contact time: not estimated (" << n.contact_source << ")";
  }
  out << "\n  lasting contacts: " << num(100 * n.lasting_share) << " % of the mass ("
      << n.lasting_reason << ")\n";
  bool defined = false;  // the definitions once, with the first species
  for (const SpeciesNumbers& x : n.species)
    if (std::isfinite(x.relaxation_time)) {
      out << "  " << x.name << ": relaxation time tau " << num(x.relaxation_time) << " s"
          << (defined ? "" : " (U_t / g; Stokes' rho d^2 / (18 mu) without gravity)")
          << (std::isfinite(x.stokes)
                  ? ", Stokes number " + num(x.stokes) + (defined ? "" : " (tau U / L, L the domain along the flow)")
                  : std::string())
          << "\n";
      defined = true;
    }
  if (std::isfinite(n.mass_loading))
    out << "  mass loading " << num(n.mass_loading) << ", relaxation time / fluid step "
        << num(n.step_ratio) << ", gas cell / diameter " << num(n.cell_ratio) << "\n";
  if (std::isfinite(n.tube_ratio))
    out << "  " << (n.tube ? "tube" : "narrowest lateral extent") << " / diameter "
        << num(n.tube_ratio) << "\n";
  for (const Advice& a : advice)
    out << "  " << a.topic << ": " << a.choice
        << (a.differs ? " (the scene has " + a.scene + ")" : std::string()) << " - " << a.reason
        << "\n";
  return out.str();
}

}  // namespace carom
