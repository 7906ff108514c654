// carom_bench: collisions per second of the elastic hard-sphere fluid, with the physics printed
// beside the speed so that speed is never bought with wrong physics.
//
//   carom_bench --n 32000 --phi 0.40
//   carom_bench --n 100000 --phi 0.3 --ratio 0.2 --fines 0.5
//   carom_bench --n 32000 --phi 0.40 --threads 2     (then compare collisions_per_second)
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>

#include "tests/bench/fluid_run.hpp"

using namespace carom;

int main(int argc, char** argv) {
  CLI::App app{"carom_bench: event-driven hard-sphere fluid benchmark"};
  GranularGasSpec spec;
  // A lattice start needs to melt first: near freezing (phi >= 0.4) that takes of order a
  // hundred collisions per particle (at phi = 0.45, after 5 the pressure is still 9 % below
  // Carnahan-Starling; after 200 it agrees to 0.01 %).
  double equilibrate = -1.0, measure = 20.0, level_ratio = -1.0;
  app.add_option("--n", spec.count, "number of particles (monodisperse: rounded to 4 k^3)");
  app.add_option("--phi", spec.volume_fraction, "solid volume fraction")->check(CLI::Range(0.001, 0.7));
  app.add_option("--ratio", spec.fines_diameter_ratio, "fines / large diameter ratio (1: monodisperse)");
  app.add_option("--fines", spec.fines_number_fraction, "number fraction of fines");
  app.add_option("--equilibrate", equilibrate,
                 "collisions per particle before measuring (default 10, or 150 for phi >= 0.4)");
  app.add_option("--measure", measure, "collisions per particle measured");
  app.add_option("--grid-ratio", level_ratio, "grid levels: < 0 cheapest (default), 0 one grid, > 0 size ratio that starts a level");
  app.add_option("--seed", spec.seed, "random seed");
  int subdivision = 0;
  app.add_option("--subdivision", subdivision, "grid cells per diameter (1..3; 0: chosen per level)");
  int threads = 1;
  app.add_option(
         "--threads", threads,
         "threads of the run (default 1: collisions per CPU second compare single cores; "
         "with 2, a collision's two predictions run at once: compare collisions_per_second)")
      ->check(CLI::Range(1, 1024));
  std::size_t prefetch_from = EventDrivenOptions{}.prefetch_from;
  app.add_option("--prefetch-from", prefetch_from,
                 "particles from which the engine's loading hints are on (hints: the same events)");
  CLI11_PARSE(app, argc, argv);

  if (equilibrate < 0.0) equilibrate = spec.volume_fraction >= 0.4 ? 150.0 : 10.0;
  EventDrivenOptions options;
  options.grid_level_ratio = level_ratio;
  options.grid_subdivision = subdivision;
  options.check_invariants = false;
  options.threads = threads;
  options.prefetch_from = prefetch_from;
  // The engine gets the particles without a copy kept here (which held them twice: 116 bytes a
  // particle of the peak memory at N = 1e6).
  bench::FluidRun run(spec, options);
  EventDrivenEngine& sim = run.engine();
  const std::size_t n = sim.particle_count();
  std::printf("particles=%zu species=%zu grid_levels=%zu box=%.4g\n", n, sim.system().species.size(),
              sim.grid().levels().size(), sim.system().domain.length().x());
  for (const auto& level : sim.grid().levels())
    std::printf("  level: %d x %d x %d cells of %.4g, %d per diameter\n", level.cells[0], level.cells[1],
                level.cells[2], level.cell_size.x(), level.reach);

  run.run_per_particle(equilibrate);

  const RunStatistics before = sim.statistics();
  const double t0 = sim.time();
  const double cpu0 = bench::cpu_seconds();
  const auto wall0 = std::chrono::steady_clock::now();
  run.run_per_particle(measure);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double cpu = bench::cpu_seconds() - cpu0;
  const RunStatistics& after = sim.statistics();
  const std::uint64_t collisions = after.pair_events - before.pair_events;

  const bench::FluidRun::Physics physics = run.physics_since(before, t0);
  const double temperature = physics.temperature;
  std::printf("temperature=%.6f\n", temperature);
  std::printf("pressure=%.5f\n", physics.pressure);
  std::printf("collision_rate=%.5f\n", physics.collision_rate);
  if (sim.system().species.size() == 1) {
    std::printf("enskog_pressure=%.5f\n", run.enskog_pressure());
    std::printf("enskog_collision_rate=%.5f\n", run.enskog_collision_rate(temperature));
  }
  std::printf("cpu_seconds=%.3f collisions_per_cpu_second=%.0f\n", cpu, collisions / cpu);
  std::printf("events=%llu invalid_events=%llu cell_crossings=%llu wall_seconds=%.3f\n",
              static_cast<unsigned long long>(after.events - before.events),
              static_cast<unsigned long long>(after.invalid_events - before.invalid_events),
              static_cast<unsigned long long>(after.cell_crossings - before.cell_crossings), wall);
  std::printf("collisions_per_second=%.0f\n", collisions / wall);
  return 0;
}
