// Runs of a fines-rich mixture on the cost model's grid levels against the same run on one grid.
//
// With several levels, the cells of the fines are widened beyond their diameter, the other
// levels are scanned in batches, and after a cell crossing only the cells that came into reach
// are searched (the pending collision is kept). One grid for every size (grid_level_ratio = 0)
// shares none of that: its cells hold every particle, and a crossing searches one face layer of
// its own block. Both must process the same collisions in the same order. The states are
// compared after about 1.7 collisions per particle (2600 collisions): the two runs compute
// pair times from states advanced at other events, so they differ by round-off, which every
// collision amplifies (measured: 1.6e-10 for straight flights, 5.8e-10 under gravity, in m and
// m/s of particles of diameter 1 and 0.1 moving at 1 to 6 m/s). The tolerance 1e-7 leaves that
// room, and a missed or spurious collision changes a velocity by order 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "events/event_driven/engine.hpp"
#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

/// The 3000-particle mixture of 97 % fines of a tenth of the diameter (phi = 0.3).
System fines_mixture(std::uint64_t seed) {
  GranularGasSpec spec;
  spec.count = 3000;
  spec.volume_fraction = 0.3;
  spec.fines_diameter_ratio = 0.1;
  spec.fines_number_fraction = 0.97;
  spec.seed = seed;
  return make_granular_gas(spec);
}

/// Runs `system` to t = 0.012 on the grid levels of `levels` and on one grid, with every
/// collision checked for overlaps, and compares the final states.
void expect_same_run_on_one_grid(const System& system, EventDrivenOptions levels,
                                 std::size_t level_count) {
  EventDrivenOptions one_grid;
  levels.check_invariants = one_grid.check_invariants = true;
  one_grid.grid_level_ratio = 0.0;
  EventDrivenEngine a(system, levels), b(system, one_grid);
  ASSERT_EQ(a.grid().levels().size(), level_count);
  ASSERT_EQ(b.grid().levels().size(), 1u);
  const double end = 0.012;
  a.run_until(end);
  b.run_until(end);
  ASSERT_GT(a.statistics().pair_events, system.particles.size() / 4) << "too short to test anything";
  EXPECT_GT(a.statistics().cell_crossings, 2 * a.statistics().pair_events);
  EXPECT_EQ(a.statistics().pair_events, b.statistics().pair_events);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.particle_count(); ++i) {
    Vec3 dr = a.position(i) - b.position(i);
    system.domain.minimum_image(dr);
    worst = std::max({worst, dr.norm(), (a.velocity(i) - b.velocity(i)).norm()});
  }
  EXPECT_LT(worst, 1e-7);
}

void expect_cost_model_run_on_one_grid(const Vec3& gravity) {
  System system = fines_mixture(11);
  system.flight.gravity = gravity;
  const EventDrivenEngine probe(system, EventDrivenOptions{});
  ASSERT_GE(probe.grid().levels()[1].cell_size.x(), 1.5 * 0.1) << "the fines' cells are not widened";
  expect_same_run_on_one_grid(system, EventDrivenOptions{}, 2);
}

TEST(GridLevelsRun, StraightFlightsMatchOneGrid) {
  expect_cost_model_run_on_one_grid(Vec3::Zero());
}

TEST(GridLevelsRun, FlightsUnderGravityMatchOneGrid) {
  expect_cost_model_run_on_one_grid(Vec3(0.3, -0.2, -1.0));
}

// Levels that each hold a range of sizes: the fines' radii spread over [low, 1] of theirs and
// the large ones' over [0.6, 1] (0.8 in the second case), levels started at every halving
// (grid_level_ratio = 0.5: three levels, then two). Before the other levels' cells were grown by
// the same reach from both sides (HierarchicalGrid::reach_between), a small particle's crossing
// missed partners that a large one of its level would have reached, and both runs stopped on an
// overlap (at t = 0.0089 and 0.0051 s).
TEST(GridLevelsRun, PolydisperseLevelsMatchOneGrid) {
  struct Spread {
    std::uint64_t seed;
    double fines_low, large_low;
    std::size_t levels;
  };
  for (const Spread& c : {Spread{12, 0.3, 0.6, 3}, Spread{13, 0.5, 0.8, 2}}) {
    SCOPED_TRACE(c.seed);
    System system = fines_mixture(c.seed);
    Rng rng(c.seed);
    const double large = *std::max_element(system.particles.radius.begin(),
                                           system.particles.radius.end());
    for (double& r : system.particles.radius)  // smaller only: no overlaps
      r *= std::lerp(r > 0.5 * large ? c.large_low : c.fines_low, 1.0, rng.uniform());
    EventDrivenOptions levels;
    levels.grid_level_ratio = 0.5;
    expect_same_run_on_one_grid(system, levels, c.levels);
  }
}

// The full predictions of the large spheres skip the fines' cells that hold no contact before
// the earliest found so far (scan_finer_level_near, from a bound on the fines' speeds): with and
// without (EventDrivenOptions::skip_unreachable_cells) the run is the same bit for bit, in the
// periodic box and with walls in z, frictional and inelastic with the TC model (particles pressed beyond a wall
// sit in the edge cells, which reach beyond the box). Debug builds also check every skipping
// prediction against the walk of every covering cell.
TEST(GridLevelsRun, SkippingTheFinesCellsChangesNothing) {
  for (const bool walls : {false, true}) {
    SCOPED_TRACE(walls ? "walls in z" : "periodic");
    System system = fines_mixture(21);
    if (walls) {  // the gas moved up by half a large diameter into a box one diameter taller
      for (Vec3& r : system.particles.position) r.z() += 0.55;
      system.domain.upper.z() += 1.1;
      system.domain.periodic = {true, true, false};
      system.walls = box_walls(system.domain);
      system.materials = MaterialTable(system.species.size(), system.walls.size(),
                                       ContactLaw{0.9, 0.2, 0.3}, ContactLaw{0.9, 0.2, 0.3});
    }
    EventDrivenOptions skipping, plain;
    plain.skip_unreachable_cells = false;
    skipping.check_invariants = plain.check_invariants = true;
    // The TC model: fines caught between a large sphere and a wall collapse without it.
    skipping.collapse.contact_time = plain.collapse.contact_time = 1e-4;
    EventDrivenEngine a(system, skipping), b(system, plain);
    ASSERT_EQ(a.grid().levels().size(), 2u);
    a.run_until(0.03);
    b.run_until(0.03);
    ASSERT_GT(a.statistics().pair_events, system.particles.size()) << "too short to test anything";
    if (walls) {
      EXPECT_GT(a.statistics().wall_events, 100u);
    }
    EXPECT_EQ(a.statistics().invalid_events, b.statistics().invalid_events);
    test::expect_same_runs(a, b);
  }
}

}  // namespace
}  // namespace carom
