// The cost of one flow step (events/flow/flow_boundaries.hpp) against the number of particles
// present N and the particles entering per step k: the step should cost O(N + k attempts), not
// O(N k). Particles (2 mm) are spread over a 10 cm x 10 cm x height box (volume fraction 0.05,
// the height grows with N) with an inlet slab on top; each row is the mean wall time of the
// steps (the first step, which allocates, left out).
//   carom_flow_bench [--steps S]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/rng.hpp"
#include "events/flow/flow_boundaries.hpp"

using namespace carom;

namespace {

double seconds_per_step(std::size_t n, double per_step, int steps) {
  System system;
  const double d = 2e-3, phi = 0.05;
  const double height = n * (3.14159265358979 / 6 * d * d * d) / (phi * 0.01) + 0.02;
  system.domain.upper = Vec3(0.1, 0.1, height);
  system.walls = box_walls(system.domain);
  system.species.push_back(Species{"glass", d, 2500.0});
  Rng rng(1);
  const Species& kind = system.species[0];
  for (std::size_t i = 0; i < n; ++i)
    system.particles.add(Vec3(rng.uniform(0.001, 0.099), rng.uniform(0.001, 0.099),
                              rng.uniform(0.001, height - 0.02)),
                         Vec3(0, 0, -1), Vec3::Zero(), kind.radius(), kind.mass(), kind.inertia(),
                         0, i);
  Inflow in;
  in.name = "top";
  in.axis = 2;
  in.plane = height - 0.005;
  in.direction = -1;
  in.upper = Vec3(0.1, 0.1, 0.0);
  in.mass_flow = per_step / 1e-3 * kind.mass();
  in.velocity = Vec3(0, 0, -1);
  FlowBoundaries flow({in}, {Outflow{"floor", 2, 0.0005, -1}}, system, 1, 0.0, 1e-3);
  ParticleStore particles = system.particles;
  double total = 0.0;
  for (int s = 0; s <= steps; ++s) {
    ParticleChange change;
    const auto start = std::chrono::steady_clock::now();
    flow.step((s + 1) * 1e-3, particles, change);
    const auto stop = std::chrono::steady_clock::now();
    if (s > 0) total += std::chrono::duration<double>(stop - start).count();
    // The new particles fall out of the slab (as a method would move them), keeping N fixed.
    for (std::size_t j = 0; j < change.added.size(); ++j) {
      const std::size_t i = j % particles.size();
      particles.position[i] = change.added.position[j] - Vec3(0, 0, 0.01);
    }
  }
  if (flow.inflow_counters(0).blocked_steps > 0) std::printf("(blocked) ");
  return total / steps;
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 50;
  if (argc == 3 && std::strcmp(argv[1], "--steps") == 0) steps = std::atoi(argv[2]);
  std::printf("%10s %8s %14s %16s\n", "N", "k/step", "s/step", "s/(N step) [ns]");
  for (std::size_t n : {10000u, 100000u, 1000000u})
    for (double k : {10.0, 100.0}) {
      const double t = seconds_per_step(n, k, steps);
      std::printf("%10zu %8.0f %14.3e %16.2f\n", n, k, t, t / n * 1e9);
    }
  return 0;
}
