#include "scenarios/run/summary.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "carom/version.hpp"
#include "scenarios/analysis/enskog.hpp"
#include "scenarios/run/summary_units.hpp"

namespace carom {

void TimeAverages::sample(const CollisionMethod& sim) {
  const double kinetic = sim.energies().translational;
  const std::size_t n = sim.particle_count();
  const double root = n > 0 ? std::sqrt(2.0 * kinetic / (3.0 * static_cast<double>(n))) : 0.0;
  const double t = sim.time();
  if (!started_) {
    started_ = true;
    first_time_ = t;
  } else if (t > last_time_) {
    kinetic_integral_ += 0.5 * (kinetic + last_kinetic_) * (t - last_time_);
    root_temperature_integral_ += 0.5 * (root + last_root_) * (t - last_time_);
  }
  last_time_ = t;
  last_kinetic_ = kinetic;
  last_root_ = root;
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string json_number(double x) { return std::isfinite(x) ? format_number(x) : "null"; }

namespace {
/// Enskog applies to a homogeneous periodic gas: no gravity, every axis periodic, no walls.
bool enskog_applies(const System& system) {
  return !system.flight.has_gravity() && system.walls.empty() && system.domain.periodic[0] &&
         system.domain.periodic[1] && system.domain.periodic[2];
}
}  // namespace

std::string summary_json(const CollisionMethod& sim, const Scene& scene, const RunStretch& stretch) {
  const System& system = sim.system();
  const RunStatistics& now = sim.statistics();
  const RunStatistics& before = stretch.start_statistics;
  const std::size_t S = system.species.size(), W = system.walls.size();
  const double dt = sim.time() - stretch.start_time;
  const double volume = system.domain.volume();
  const std::uint64_t events = now.events - before.events;
  const std::uint64_t collisions = now.collisions() - before.collisions();

  std::vector<std::size_t> per_species(S, 0);
  for (std::uint32_t s : system.particles.species) ++per_species[s];
  // Particle-seconds of each species over the stretch: the count now times its length, or with
  // inflow and outflow the time integral of the number present.
  std::vector<double> particle_seconds(S);
  for (std::size_t s = 0; s < S; ++s) particle_seconds[s] = static_cast<double>(per_species[s]) * dt;
  if (stretch.flow != nullptr) {
    const std::vector<double> now = stretch.flow->particle_seconds_at(sim.time());
    for (std::size_t s = 0; s < S; ++s) particle_seconds[s] = now[s] - stretch.flow_start.particle_seconds[s];
  }

  std::ostringstream j;
  j << "{\n";
  j << "  \"carom_version\": " << json_string(kVersion) << ",\n";
  j << "  \"scene\": " << json_string(scene.name) << ",\n";
  if (!stretch.run_json.empty()) j << "  \"run\": " << stretch.run_json << ",\n";
  j << "  \"status\": " << json_string(stretch.status) << ",\n";
  j << "  \"message\": " << json_string(stretch.message) << ",\n";
  j << "  \"start_time\": " << json_number(stretch.start_time) << ",\n";
  j << "  \"end_time\": " << json_number(sim.time()) << ",\n";
  j << "  \"wall_seconds\": " << json_number(stretch.wall_seconds) << ",\n";
  j << "  \"particles\": " << sim.particle_count() << ",\n";
  j << "  \"events\": " << events << ",\n";
  j << "  \"collisions\": " << collisions << ",\n";
  j << "  \"events_total\": " << now.events << ",\n";
  j << "  \"collisions_total\": " << now.collisions() << ",\n";
  const double wall = stretch.wall_seconds > 0 ? stretch.wall_seconds : NAN;
  j << "  \"events_per_second\": " << json_number(events / wall) << ",\n";
  j << "  \"collisions_per_second\": " << json_number(collisions / wall) << ",\n";

  // Rate per particle of s with t: each s-s collision involves two particles of s.
  const auto pair_rates = [&](const char* key, auto count_of) {
    j << "  " << json_string(key) << ": {";
    for (std::size_t s = 0, first = 1; s < S; ++s)
      for (std::size_t t = 0; t < S; ++t, first = 0) {
        const double count = static_cast<double>(count_of(s, t)) * (s == t ? 2.0 : 1.0);
        const double rate = particle_seconds[s] > 0 ? count / particle_seconds[s] : NAN;
        j << (first ? "" : ",") << "\n    " << json_string(system.species[s].name + "-" + system.species[t].name)
          << ": " << json_number(rate);
      }
    j << "\n  },\n";
  };
  pair_rates("collision_rate_per_particle",
             [&](std::size_t s, std::size_t t) { return now.pair(s, t) - before.pair(s, t); });
  j << "  \"impact_speed\": " << json_number(system.impact_speed) << ",\n";
  pair_rates("impact_rate_per_particle",
             [&](std::size_t s, std::size_t t) { return now.pair_impact(s, t) - before.pair_impact(s, t); });

  j << "  \"enskog_rate_per_particle\": ";
  if (enskog_applies(system) && sim.particle_count() > 0) {
    std::vector<MixtureComponent> mixture;
    for (std::size_t s = 0; s < S; ++s)
      mixture.push_back({static_cast<double>(per_species[s]) / volume, system.species[s].diameter, system.species[s].mass()});
    const double root_t = stretch.averages.root_temperature();
    j << "{";
    for (std::size_t s = 0, first = 1; s < S; ++s)
      for (std::size_t t = 0; t < S; ++t, first = 0)
        j << (first ? "" : ",") << "\n    " << json_string(system.species[s].name + "-" + system.species[t].name) << ": "
          << json_number(enskog_frequency(mixture, s, t, 1.0) * root_t);
    j << "\n  },\n";
  } else {
    j << "null,\n";
  }

  // Counts per species and wall in the stretch, "s@w".
  const auto wall_counts = [&](const char* key, auto count_of) {
    j << "  " << json_string(key) << ": {";
    for (std::size_t s = 0, first = 1; s < S; ++s)
      for (std::size_t w = 0; w < W; ++w, first = 0)
        j << (first ? "" : ",") << "\n    " << json_string(system.species[s].name + "@" + system.walls[w].name)
          << ": " << count_of(s, w);
    j << (S * W > 0 ? "\n  " : "") << "},\n";
  };
  wall_counts("wall_collisions", [&](std::size_t s, std::size_t w) { return now.wall(s, w) - before.wall(s, w); });
  wall_counts("wall_impacts",
              [&](std::size_t s, std::size_t w) { return now.wall_impact(s, w) - before.wall_impact(s, w); });
  j << "  \"wall_force\": {";
  for (std::size_t w = 0; w < W; ++w) {
    const Eigen::Vector3d force = dt > 0 ? Eigen::Vector3d((now.wall_impulse[w] - before.wall_impulse[w]) / dt)
                                         : Eigen::Vector3d::Constant(NAN);
    j << (w ? "," : "") << "\n    " << json_string(system.walls[w].name) << ": [" << json_number(force.x()) << ", "
      << json_number(force.y()) << ", " << json_number(force.z()) << "]";
  }
  j << (W ? "\n  " : "") << "},\n";

  const std::size_t n = sim.particle_count();
  const double kinetic = stretch.averages.kinetic_energy();
  const double p_kin = 2.0 * kinetic / (3.0 * volume);
  const double p_coll = dt > 0 ? (now.virial - before.virial).trace() / (3.0 * volume * dt) : NAN;
  j << "  \"mean_temperature\": " << json_number(n > 0 ? 2.0 * kinetic / (3.0 * static_cast<double>(n)) : NAN) << ",\n";
  j << "  \"pressure\": {\"kinetic\": " << json_number(p_kin) << ", \"collisional\": " << json_number(p_coll)
    << ", \"total\": " << json_number(p_kin + p_coll) << "},\n";
  const Energies e = sim.energies();
  j << "  \"energy\": {\"translational\": " << json_number(e.translational) << ", \"rotational\": " << json_number(e.rotational)
    << ", \"potential\": " << json_number(e.potential) << ", \"elastic\": " << json_number(e.elastic)
    << ", \"dissipated\": " << json_number(e.dissipated) << ", \"gas_work\": " << json_number(e.gas_work) << "},\n";
  const std::vector<MethodQuantity> quantities = sim.quantities();
  j << "  \"method\": {\"kind\": " << json_string(std::string(sim.kind()));
  for (const MethodQuantity& q : quantities) j << ", " << json_string(q.name) << ": " << json_number(q.value);
  j << "},\n";
  j << "  \"simulated_seconds_per_wall_second\": "
    << json_number(stretch.wall_seconds > 0 ? dt / stretch.wall_seconds : NAN);
  if (stretch.gas != nullptr) {
    const CouplingTimes& t = stretch.gas->times();
    const CouplingTimes& t0 = stretch.gas_start;
    const double mapping = t.mapping - t0.mapping, solve = t.solve - t0.solve,
                 interpolation = t.interpolation - t0.interpolation;
    j << ",\n  \"gas\": {\"fluid_steps\": " << (t.steps - t0.steps)
      << ", \"unconverged_steps\": " << (t.unconverged_steps - t0.unconverged_steps)
      << ", \"mapping_seconds\": " << json_number(mapping) << ", \"solve_seconds\": " << json_number(solve)
      << ", \"interpolation_seconds\": " << json_number(interpolation)
      << ", \"event_seconds\": " << json_number(stretch.wall_seconds - mapping - solve - interpolation) << "}";
  }
  if (stretch.flow != nullptr)
    j << ",\n  \"flow\": " << flow_summary_json(*stretch.flow, stretch.flow_start, stretch.start_time, sim.time());
  if (!stretch.analysis_json.empty()) j << ",\n  \"analysis\": " << stretch.analysis_json;
  // Last, below the numbers a reader looks for first: the unit of every key (summary_units.hpp).
  j << ",\n  \"units\": " << summary_units_json();
  j << "\n}\n";
  return j.str();
}

void write_text_atomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) {
      out.close();
      std::remove(temporary.c_str());  // a full disk: leave no half file behind
      throw std::runtime_error(temporary + ": cannot write");
    }
  }
  std::filesystem::rename(temporary, path);
}

}  // namespace carom
