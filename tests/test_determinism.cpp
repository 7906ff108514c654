// Determinism (core/DESIGN.md, "Events and the calendar"): the same system run twice gives
// bit-identical states, and EventDrivenEngine::state() + the restoring constructor continue bit for
// bit like the uninterrupted run. Exact (bitwise) comparison: anything else is not determinism.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void expect_identical(const EngineState& a, const EngineState& b) {
  const ParticleStore &p = a.particles, &q = b.particles;
  EXPECT_TRUE(same_bits(p.position, q.position)) << "positions differ";
  EXPECT_TRUE(same_bits(p.velocity, q.velocity)) << "velocities differ";
  EXPECT_TRUE(same_bits(p.spin, q.spin)) << "spins differ";
  EXPECT_TRUE(same_bits(p.clock, q.clock)) << "clocks differ";
  EXPECT_TRUE(same_bits(a.event_counters, b.event_counters)) << "event counters differ";
  EXPECT_TRUE(same_bits(a.last_collision, b.last_collision));
  EXPECT_TRUE(same_bits(p.id, q.id));
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.statistics.events, b.statistics.events);
  EXPECT_EQ(a.statistics.pair_events, b.statistics.pair_events);
  EXPECT_EQ(a.statistics.wall_events, b.statistics.wall_events);
  EXPECT_EQ(a.statistics.pair_collisions, b.statistics.pair_collisions);
  EXPECT_EQ(std::memcmp(&a.statistics.dissipated_energy, &b.statistics.dissipated_energy, sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(a.statistics.virial.data(), b.statistics.virial.data(), 9 * sizeof(double)), 0);
}

// A rough inelastic bidisperse periodic gas (e = 0.95, mu = 0.3, beta0 = 0.2) with a sample action.
System rough_mixture() {
  GranularGasSpec spec;
  spec.count = 400;
  spec.volume_fraction = 0.25;
  spec.fines_diameter_ratio = 0.4;
  spec.fines_number_fraction = 0.5;
  spec.seed = 9;
  System system = make_granular_gas(spec);
  system.materials = MaterialTable(system.species.size(), 0, ContactLaw{0.95, 0.3, 0.2}, ContactLaw{});
  return system;
}

TEST(Determinism, SameSystemTwiceIsBitIdentical) {
  auto run = [] {
    EventDrivenEngine sim(rough_mixture());
    int samples = 0;
    sim.add_periodic_action("sample", 0.125, 0.125, [&] { ++samples; });  // exact binary times
    sim.run_until(3.0);
    EXPECT_EQ(samples, 23) << "0.125, 0.25, ..., 2.875: an action due exactly at the end time comes after the end";
    return sim.state();
  };
  const EngineState a = run(), b = run();
  EXPECT_GT(a.statistics.pair_events, 2000u);
  expect_identical(a, b);
}

// The loading hints of large systems (EventDrivenOptions::prefetch_from: the partner's records,
// the cells' first particles, the candidates' records, calendar blocks; and the candidate walk
// compiled with them) change nothing: the rough mixture with them from the first particle on,
// against the run without them (it has too few particles for the default), bit for bit; with
// and without gravity (the walk of each flight).
TEST(Determinism, LoadingHintsChangeNothing) {
  for (const bool gravity : {false, true}) {
    auto run = [&](std::size_t prefetch_from) {
      System system = rough_mixture();
      if (gravity) system.flight.gravity = Vec3(0.3, 0.0, -2.0);
      EventDrivenOptions options;
      options.prefetch_from = prefetch_from;
      EventDrivenEngine sim(std::move(system), options);
      sim.run_until(3.0);
      return sim.state();
    };
    const EngineState hinted = run(0), plain = run(EventDrivenOptions{}.prefetch_from);
    EXPECT_GT(hinted.statistics.pair_events, 2000u) << "gravity " << gravity;
    expect_identical(hinted, plain);
  }
}

TEST(Determinism, RestoredStateContinuesBitForBit) {
  const System system = rough_mixture();
  EventDrivenEngine uninterrupted(system);
  int samples_a = 0, samples_b = 0;
  uninterrupted.add_periodic_action("sample", 0.125, 0.125, [&] { ++samples_a; });
  uninterrupted.run_until(1.234);
  const EngineState saved = uninterrupted.state();
  uninterrupted.run_until(3.0);

  EventDrivenEngine restored(system, EventDrivenOptions{}, saved);
  restored.add_periodic_action("sample", 0.125, 0.125, [&] { ++samples_b; });
  restored.run_until(3.0);
  EXPECT_EQ(samples_a, 23);
  EXPECT_EQ(samples_b, 23 - 9) << "the action resumes at its saved next time";
  expect_identical(uninterrupted.state(), restored.state());
}

// A damaged checkpoint whose saved grid cell lies outside the grid (the fuzzer's find: it
// crashed the restore by indexing past the cell lists) is refused with what is wrong, on every
// axis and both sides; the undamaged state restores.
TEST(Determinism, RestoreRefusesACellOutsideTheGrid) {
  const System system = rough_mixture();
  EventDrivenEngine sim(system);
  sim.run_until(0.5);
  const EngineState saved = sim.state();
  EXPECT_NO_THROW(EventDrivenEngine(system, EventDrivenOptions{}, saved));
  for (int axis = 0; axis < 3; ++axis)
    for (int bad : {-1, 1 << 20}) {
      EngineState damaged = saved;
      damaged.cells[3][axis] = bad;
      try {
        EventDrivenEngine restored(system, EventDrivenOptions{}, damaged);
        ADD_FAILURE() << "cell " << bad << " on axis " << axis << " was accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("is outside its grid level"), std::string::npos) << e.what();
      }
    }
}

// A damaged checkpoint whose species index lies beyond the scene's species (the fuzzer's find:
// the restore read past the species list), or whose counters are sized for other species, is
// refused with what is wrong.
TEST(Determinism, RestoreRefusesASpeciesBeyondTheScene) {
  const System system = rough_mixture();
  EventDrivenEngine sim(system);
  sim.run_until(0.5);
  const EngineState saved = sim.state();
  EngineState damaged = saved;
  damaged.particles.species[5] = static_cast<std::uint32_t>(system.species.size());
  try {
    EventDrivenEngine restored(system, EventDrivenOptions{}, damaged);
    ADD_FAILURE() << "a species index beyond the scene was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has species index"), std::string::npos) << e.what();
  }
  damaged = saved;
  damaged.statistics.resize(system.species.size() + 1, system.walls.size());
  EXPECT_THROW(EventDrivenEngine(system, EventDrivenOptions{}, damaged), std::invalid_argument);
}

// A damaged checkpoint with a radius, a state or a flight that is not a finite number is refused
// before the grid turns it into cell indices (fuzzing found a NaN radius reaching the grid).
TEST(Determinism, RestoreRefusesNonFiniteRadiiAndStates) {
  const System system = rough_mixture();
  EventDrivenEngine sim(system);
  sim.run_until(0.5);
  const EngineState saved = sim.state();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::function<void(EngineState&)>> damages = {
      [&](EngineState& s) { s.particles.radius[3] = nan; },
      [&](EngineState& s) { s.particles.radius[3] = -0.5; },
      [&](EngineState& s) { s.particles.radius[3] = inf; },
      [&](EngineState& s) { s.particles.position[3].x() = nan; },
      [&](EngineState& s) { s.particles.velocity[3].y() = inf; },
      [&](EngineState& s) { s.particles.spin[3].z() = nan; },
      [&](EngineState& s) { s.particles.clock[3] = nan; },
      // A flight out of range would escape the bounds the relax predictions put on all of them.
      [&](EngineState& s) { s.flights[3].rate = nan; },
      [&](EngineState& s) { s.flights[3].rate = -1.0; },
      [&](EngineState& s) { s.flights[3].drive.x() = inf; }};
  for (std::size_t k = 0; k < damages.size(); ++k) {
    EngineState damaged = saved;
    damages[k](damaged);
    try {
      EventDrivenEngine restored(system, EventDrivenOptions{}, damaged);
      ADD_FAILURE() << "damage " << k << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("that is not finite"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(EventDrivenEngine(system, EventDrivenOptions{}, saved));
}

// The same with walls, gravity and the TC model (a slab one grid cell high).
TEST(Determinism, RestoredStateContinuesBitForBitWithWallsAndGravity) {
  test::expect_finishes(20, [] {
                System system;
                system.domain.upper = Vec3(8, 8, 1.9);
                system.species = {Species{"big", 1.0, 1000.0}, Species{"small", 0.5, 1000.0}};
                system.walls = box_walls(system.domain);
                system.materials = MaterialTable(2, system.walls.size(), ContactLaw{0.8, 0.4, 0.3},
                                                 ContactLaw{0.7, 0.5, 0.0});
                system.flight.gravity = Vec3(0, 0, -9.81);
                Rng rng(4);
                for (int k = 0; k < 40; ++k)
                  system.add_particle(k % 2, Vec3(0.6 + 1.1 * (k % 7), 0.6 + 1.1 * (k / 7), 0.6 + 0.6 * rng.uniform()),
                                      3.0 * rng.normal3(), 3.0 * rng.normal3());
                EventDrivenOptions options;
                options.collapse.contact_time = 1e-4;
                EventDrivenEngine a(system, options);
                a.run_until(0.7);
                const EngineState saved = a.state();
                a.run_until(2.0);
                EventDrivenEngine b(system, options, saved);
                b.run_until(2.0);
                EXPECT_GT(a.statistics().collisions(), 1000u);
                expect_identical(a.state(), b.state());
              });
}

}  // namespace
}  // namespace carom
