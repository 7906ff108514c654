// carom_scale_bench: how much of its small-system speed the hard-sphere fluid keeps at a large
// N (the large-N speed goal), measured in one process: both systems are built and equilibrated,
// then timed in alternating windows of the same number of collisions, each pair of windows giving
// one ratio. The host's drift (it moves single five-minute runs by 15 %) then hits both sides of
// each ratio alike, as alternating runs of two binaries do.
//
//   carom_scale_bench --large 1000000 --small 10000 --phi 0.40 --equilibrate 200 --pairs 21
//
// Each row: the pair, both rates (million collisions per CPU second) and large / small. Then
// the median ratio with its quartiles and spread, and each system's pressure and collision
// rate over its timed windows beside Enskog's, so that speed is never bought with wrong
// physics. Before each timed window the system runs a twentieth of a window untimed, so that
// neither side is timed while it loads its working set back into the caches.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tests/bench/fluid_run.hpp"

using namespace carom;

namespace {

/// One system's timed windows.
struct Side {
  bench::FluidRun run;
  RunStatistics before{};
  double t0 = 0, cpu = 0;
  std::uint64_t collisions = 0;

  /// Runs a warm-up of window / 20 collisions, then times `window` collisions; returns their
  /// rate in collisions per CPU second.
  double timed_window(std::uint64_t window) {
    run.run_collisions(window / 20);
    const std::uint64_t start = run.engine().statistics().pair_events;
    const double cpu0 = bench::cpu_seconds();
    run.run_collisions(window);
    const double seconds = bench::cpu_seconds() - cpu0;
    const std::uint64_t done = run.engine().statistics().pair_events - start;
    cpu += seconds;
    collisions += done;
    return static_cast<double>(done) / seconds;
  }
  void print_physics(const char* name) const {
    const bench::FluidRun::Physics p = run.physics_since(before, t0);
    std::printf("%s: particles=%zu temperature=%.6f pressure=%.5f collision_rate=%.5f "
                "enskog_pressure=%.5f enskog_collision_rate=%.5f collisions_per_cpu_second=%.0f\n",
                name, run.size(), p.temperature, p.pressure, p.collision_rate, run.enskog_pressure(),
                run.enskog_collision_rate(p.temperature),
                static_cast<double>(collisions) / cpu);
  }
};

/// The value below which a fraction q of the sorted values lie (linear between neighbours).
double quantile(const std::vector<double>& sorted, double q) {
  const double at = q * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (at - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"carom_scale_bench: a large fluid's speed against a small one's, in alternating windows"};
  GranularGasSpec large_spec, small_spec;
  large_spec.count = 1000000;
  small_spec.count = 10000;
  large_spec.volume_fraction = 0.40;
  double equilibrate = 200.0, window = 1.0e6;
  int pairs = 21;
  app.add_option("--large", large_spec.count, "particles of the large system (rounded to 4 k^3)");
  app.add_option("--small", small_spec.count, "particles of the small system (rounded to 4 k^3)");
  app.add_option("--phi", large_spec.volume_fraction, "solid volume fraction of both")
      ->check(CLI::Range(0.001, 0.7));
  app.add_option("--equilibrate", equilibrate,
                 "collisions per particle of each system before the first window (the large system's "
                 "particles leave their lattice order)")
      ->check(CLI::Range(0.0, 1.0e6));
  app.add_option("--window", window, "collisions of each timed window, both systems")->check(CLI::Range(1.0e3, 1.0e12));
  app.add_option("--pairs", pairs, "pairs of windows (each gives one ratio)")->check(CLI::Range(1, 100000));
  app.add_option("--seed", large_spec.seed, "random seed of both");
  CLI11_PARSE(app, argc, argv);
  small_spec.volume_fraction = large_spec.volume_fraction;
  small_spec.seed = large_spec.seed;

  EventDrivenOptions options;
  options.check_invariants = false;
  options.threads = 1;  // rates per CPU second of one core, as carom_bench's
  // The large system first: its arrays are then laid out as in a run of its own.
  Side large{bench::FluidRun(large_spec, options)};
  Side small{bench::FluidRun(small_spec, options)};
  std::printf("large: %zu particles, small: %zu, phi = %g; equilibrating %g collisions per particle\n",
              large.run.size(), small.run.size(), large_spec.volume_fraction, equilibrate);
  std::fflush(stdout);
  for (Side* side : {&large, &small}) {
    side->run.run_per_particle(equilibrate);
    side->before = side->run.engine().statistics();
    side->t0 = side->run.engine().time();
  }

  // Odd pairs time the large system first, even ones the small: a drift within a pair then
  // favours neither side over the whole set.
  const auto per_window = static_cast<std::uint64_t>(window);
  std::vector<double> ratios;
  for (int k = 1; k <= pairs; ++k) {
    double large_rate = 0, small_rate = 0;
    if (k % 2 == 1) {
      large_rate = large.timed_window(per_window);
      small_rate = small.timed_window(per_window);
    } else {
      small_rate = small.timed_window(per_window);
      large_rate = large.timed_window(per_window);
    }
    ratios.push_back(large_rate / small_rate);
    std::printf("pair %d: large %.4f small %.4f million collisions per cpu second, ratio %.4f\n", k,
                large_rate * 1e-6, small_rate * 1e-6, ratios.back());
    std::fflush(stdout);
  }
  std::sort(ratios.begin(), ratios.end());
  std::printf("median ratio large/small: %.4f (quartiles %.4f %.4f, min %.4f, max %.4f, %d pairs)\n",
              quantile(ratios, 0.5), quantile(ratios, 0.25), quantile(ratios, 0.75), ratios.front(),
              ratios.back(), pairs);
  large.print_physics("large");
  small.print_physics("small");
  return 0;
}
