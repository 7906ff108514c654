#pragma once
/// Slow, obviously-correct helpers shared by the tests (brute-force oracles and kinetic theory).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "events/event_driven/engine.hpp"

namespace carom::test {

/// Largest overlap of any pair, relative to its contact distance, by an all-pairs O(N^2) scan
/// of the positions at the simulator's current time (minimum image on periodic axes).
inline double max_relative_overlap(const EventDrivenEngine& sim) {
  const std::size_t n = sim.particle_count();
  const auto& radius = sim.system().particles.radius;
  std::vector<Vec3> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = sim.position(i);
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      Vec3 dr = r[i] - r[j];
      sim.system().domain.minimum_image(dr);
      const double contact = radius[i] + radius[j];
      worst = std::max(worst, (contact - dr.norm()) / contact);
    }
  return worst;
}

/// The two runs' particles, event counts and collision counts are the same bit for bit.
inline void expect_same_runs(const EventDrivenEngine& a, const EventDrivenEngine& b) {
  EXPECT_EQ(a.statistics().pair_events, b.statistics().pair_events);
  EXPECT_EQ(a.statistics().wall_events, b.statistics().wall_events);
  EXPECT_EQ(a.statistics().cell_crossings, b.statistics().cell_crossings);
  for (std::size_t i = 0; i < a.particle_count(); ++i) {
    ASSERT_EQ(a.position(i), b.position(i)) << "particle " << i;
    ASSERT_EQ(a.velocity(i), b.velocity(i)) << "particle " << i;
    ASSERT_EQ(a.spin(i), b.spin(i)) << "particle " << i;
  }
}

/// Largest overlap of a particle with a wall, relative to its radius.
inline double max_relative_wall_overlap(const EventDrivenEngine& sim) {
  double worst = 0.0;
  const auto& radius = sim.system().particles.radius;
  for (std::size_t i = 0; i < sim.particle_count(); ++i)
    for (const Wall& wall : sim.system().walls)
      worst = std::max(worst, -wall.gap(sim.position(i), radius[i]) / radius[i]);
  return worst;
}

/// Carnahan-Starling contact value g0(phi) of the monodisperse hard-sphere fluid.
inline double carnahan_starling_g0(double phi) {
  return (1.0 - 0.5 * phi) / std::pow(1.0 - phi, 3);
}

/// Enskog collision frequency per particle, omega = 4 n s^2 g0 sqrt(pi T / m), 1/s.
inline double enskog_collision_rate(double number_density, double diameter, double phi,
                                    double temperature, double mass) {
  return 4.0 * number_density * diameter * diameter * carnahan_starling_g0(phi) *
         std::sqrt(std::numbers::pi * temperature / mass);
}

/// Runs until at least `pair_collisions` more pair collisions have happened, in slices of dt.
inline void run_collisions(EventDrivenEngine& sim, std::uint64_t pair_collisions, double dt) {
  const std::uint64_t target = sim.statistics().pair_events + pair_collisions;
  while (sim.statistics().pair_events < target) sim.run_until(sim.time() + dt);
}

/// Translational kinetic temperature per particle, T = 2 KE / (3 (N - 1)) (total momentum is
/// zero in the periodic gases, so N - 1 particles carry the thermal motion; k = 1).
inline double kinetic_temperature(const EventDrivenEngine& sim) {
  return 2.0 * sim.energies().translational / (3.0 * (double(sim.particle_count()) - 1.0));
}

}  // namespace carom::test

#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace carom::test {

/// Runs `body` in a forked child that is killed by SIGALRM after `seconds`: a run that hangs
/// (an event loop that never reaches its end time) becomes a test failure with the child's
/// output, instead of a stuck test. GoogleTest failures inside the child make it exit with 1.
/// Use as: EXPECT_EXIT(test::finish_within(10, [&] { ... }), ::testing::ExitedWithCode(0), "");
/// Forwards GoogleTest failures to stderr, which is what a death test shows of its child.
struct StderrFailures : ::testing::EmptyTestEventListener {
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (result.failed())
      std::fprintf(stderr, "%s:%d: %s\n", result.file_name() ? result.file_name() : "?", result.line_number(),
                   result.message());
  }
};

template <class Body>
[[noreturn]] void finish_within(unsigned seconds, Body&& body) {
  ::testing::UnitTest::GetInstance()->listeners().Append(new StderrFailures);
  ::alarm(seconds);
  body();
  std::exit(::testing::Test::HasFailure() ? 1 : 0);
}

/// Expects `body` to pass and to finish within `seconds` (watchdog in a child process). With
/// CAROM_TEST_NO_WATCHDOG=1 in the environment it runs in-process, to see the failures in full.
template <class Body>
void expect_finishes(unsigned seconds, Body&& body) {
  if (std::getenv("CAROM_TEST_NO_WATCHDOG")) {
    body();
    return;
  }
  EXPECT_EXIT(finish_within(seconds, body), ::testing::ExitedWithCode(0), "")
      << "failed, or did not finish within " << seconds
      << " s (killed by the watchdog); rerun with CAROM_TEST_NO_WATCHDOG=1 to see the failures";
}

}  // namespace carom::test
