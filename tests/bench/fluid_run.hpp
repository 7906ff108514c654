#pragma once
// The benchmarks' hard-sphere fluid: an engine on a periodic granular gas, run by whole numbers
// of collisions, with the CPU clock the rates are given in. Shared by carom_bench (one system)
// and carom_scale_bench (two sizes in alternating windows of one process).
#include <cmath>
#include <cstdint>
#include <ctime>
#include <numbers>

#include "events/event_driven/engine.hpp"
#include "scenarios/scene/granular_gas.hpp"

namespace carom::bench {

/// CPU seconds of this process.
inline double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

class FluidRun {
 public:
  FluidRun(const GranularGasSpec& spec, const EventDrivenOptions& options)
      : spec_(spec), sim_(make_granular_gas(spec), options) {
    // Time for one collision per particle, estimated from Enskog for the large species: the
    // engine runs in steps of it until the collisions asked for are done.
    chunk_ = 1.0 / enskog_collision_rate(spec.temperature);
  }

  EventDrivenEngine& engine() { return sim_; }
  const EventDrivenEngine& engine() const { return sim_; }
  const GranularGasSpec& spec() const { return spec_; }
  std::size_t size() const { return sim_.particle_count(); }

  /// Runs until `collisions` more pair collisions are done (the step that passes the count is
  /// finished).
  void run_collisions(std::uint64_t collisions) {
    const std::uint64_t target = sim_.statistics().pair_events + collisions;
    while (sim_.statistics().pair_events < target) sim_.run_until(sim_.time() + chunk_);
  }
  /// What the benchmarks print beside the speed, over the time since the statistics `before`
  /// (taken at time t0): temperature T, reduced pressure p d^3 / T (the virial's) and
  /// collisions per particle per unit time.
  struct Physics {
    double temperature, pressure, collision_rate;
  };
  Physics physics_since(const RunStatistics& before, double t0) const {
    const RunStatistics& after = sim_.statistics();
    const double n = static_cast<double>(size()), dt = sim_.time() - t0, d = spec_.diameter;
    const Energies e = sim_.energies();
    const double temperature = 2.0 * (e.translational) / (3.0 * n);
    const double virial = (after.virial - before.virial).trace();
    const double pressure = (n * temperature + virial / (3.0 * dt)) / sim_.system().domain.volume();
    const auto collisions = static_cast<double>(after.pair_events - before.pair_events);
    return {temperature, pressure * d * d * d / temperature, 2.0 * collisions / (n * dt)};
  }

  /// Enskog's reduced pressure p d^3 / kT with the Carnahan-Starling contact value, for the
  /// large species' diameter (the monodisperse fluid's reference).
  double enskog_pressure() const {
    const double number_density = static_cast<double>(size()) / sim_.system().domain.volume();
    const double phi = spec_.volume_fraction, d = spec_.diameter;
    return number_density * d * d * d * (1 + 4 * phi * contact_value());
  }
  /// Enskog's collisions per particle per unit time at temperature T.
  double enskog_collision_rate(double temperature) const {
    const double number_density = static_cast<double>(size()) / sim_.system().domain.volume();
    const double d = spec_.diameter, mass = sim_.system().species[0].mass();
    return 4 * number_density * d * d * contact_value() * std::sqrt(std::numbers::pi * temperature / mass);
  }

  /// run_collisions of `per_particle` collisions per particle.
  void run_per_particle(double per_particle) {
    run_collisions(static_cast<std::uint64_t>(per_particle * static_cast<double>(size()) / 2));
  }

 private:
  /// Carnahan-Starling's contact value g0 at the fluid's volume fraction.
  double contact_value() const {
    const double phi = spec_.volume_fraction;
    return (1 - phi / 2) / std::pow(1 - phi, 3);
  }

  GranularGasSpec spec_;
  EventDrivenEngine sim_;
  double chunk_ = 0;
};

}  // namespace carom::bench
