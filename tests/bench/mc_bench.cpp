// carom_mc_bench: the Monte Carlo method against the event-driven one on a dilute elastic gas
// the same periodic gas, the same simulated time, wall time of each, and the error
// of the collision frequency (against Boltzmann's, the event-driven one over Enskog's g0) and
// of the velocity variance (elastic: it must stay at T0; the event-driven method keeps it to
// round-off). Usage: carom_mc_bench --n 100000 --phi 0.001 --collisions 3 [--skip-ed] [--cells K]
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "events/event_driven/engine.hpp"
#include "events/monte_carlo/engine.hpp"
#include "scenarios/scene/granular_gas.hpp"

using namespace carom;

namespace {
double temperature(const CollisionMethod& sim) {
  return 2.0 * sim.energies().translational / (3.0 * double(sim.particle_count()));
}
double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Monte Carlo against event-driven on a dilute elastic gas");
  std::size_t n = 100000;
  double phi = 1e-3, collisions = 3.0, cells_per_axis = 0.0;
  bool skip_ed = false;
  std::uint64_t seed = 1;
  app.add_option("--n", n, "particles (rounded to 4 k^3)");
  app.add_option("--phi", phi, "solid volume fraction");
  app.add_option("--collisions", collisions, "simulated time in Boltzmann collision times");
  app.add_option("--cells", cells_per_axis, "MC collision cells per axis (0: the method's default)");
  app.add_flag("--skip-ed", skip_ed, "run the Monte Carlo method only");
  app.add_option("--seed", seed, "seed");
  CLI11_PARSE(app, argc, argv);

  GranularGasSpec spec;
  spec.count = n;
  spec.volume_fraction = phi;
  spec.seed = seed;
  const System gas = make_granular_gas(spec);
  const double count = double(gas.particles.size());
  const double density = count / gas.domain.volume();
  const double boltzmann = 4.0 * density * std::sqrt(std::numbers::pi);  // d = m = T = 1
  const double g0 = (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3);
  const double duration = collisions / boltzmann;
  std::printf("N = %.0f, phi = %g, box %.1f d, simulated time %.4g (%.3g Boltzmann collision times)\n", count, phi,
              gas.domain.length().x(), duration, collisions);

  MonteCarloOptions options;
  if (cells_per_axis > 0) options.cell_size = gas.domain.length().x() / cells_per_axis;
  auto start = std::chrono::steady_clock::now();
  MonteCarloEngine mc(gas, options);
  mc.run_until(duration);
  const double mc_seconds = seconds_since(start);
  const double mc_rate = double(mc.travelling_collisions()[0]) / count / duration;
  const double t_end = temperature(mc);
  // Rate error against Boltzmann at the mean of the start and end temperatures.
  const double mc_reference = boltzmann * std::sqrt(0.5 * (1.0 + t_end));
  std::printf("monte_carlo: wall %.3f s, %llu steps of %.4g, %.1f particles a cell; rate / Boltzmann %.4f "
              "(+- %.4f counting); T_end / T0 - 1 = %+.4f\n",
              mc_seconds, (unsigned long long)mc.statistics().events, mc.time_step(),
              count / double(mc.grid().cell_count()), mc_rate / mc_reference,
              1.0 / std::sqrt(double(mc.travelling_collisions()[0])), t_end - 1.0);
  if (skip_ed) return 0;

  EventDrivenOptions ed_options;
  ed_options.check_invariants = false;
  start = std::chrono::steady_clock::now();
  EventDrivenEngine ed(gas, ed_options);
  ed.run_until(duration);
  const double ed_seconds = seconds_since(start);
  const double ed_rate = 2.0 * double(ed.statistics().pair(0, 0)) / count / duration;
  std::printf("event_driven: wall %.3f s, %llu events; rate / (Boltzmann g0) %.4f (+- %.4f counting); "
              "T_end / T0 - 1 = %+.2e\n",
              ed_seconds, (unsigned long long)ed.statistics().events, ed_rate / (boltzmann * g0),
              1.0 / std::sqrt(double(ed.statistics().pair(0, 0))), temperature(ed) - 1.0);
  std::printf("wall-time ratio event_driven / monte_carlo: %.2f\n", ed_seconds / mc_seconds);
  return 0;
}
