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

#include <cmath>

#include "events/event_driven/engine.hpp"
#include "scenarios/scene/granular_gas.hpp"

namespace carom {
namespace {

void expect_same_run_on_one_grid(const Vec3& gravity) {
  GranularGasSpec spec;
  spec.count = 3000;
  spec.volume_fraction = 0.3;
  spec.fines_diameter_ratio = 0.1;
  spec.fines_number_fraction = 0.97;
  spec.seed = 11;
  System system = make_granular_gas(spec);
  system.flight.gravity = gravity;
  EventDrivenOptions levels, one_grid;
  levels.check_invariants = one_grid.check_invariants = true;
  one_grid.grid_level_ratio = 0.0;
  EventDrivenEngine a(system, levels), b(system, one_grid);
  ASSERT_EQ(a.grid().levels().size(), 2u);
  ASSERT_GE(a.grid().levels()[1].cell_size.x(), 1.5 * 0.1) << "the fines' cells are not widened";
  ASSERT_EQ(b.grid().levels().size(), 1u);
  const double end = 0.012;
  a.run_until(end);
  b.run_until(end);
  ASSERT_GT(a.statistics().pair_events, spec.count / 2) << "too short to test anything";
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

TEST(GridLevelsRun, StraightFlightsMatchOneGrid) {
  expect_same_run_on_one_grid(Vec3::Zero());
}

TEST(GridLevelsRun, FlightsUnderGravityMatchOneGrid) {
  expect_same_run_on_one_grid(Vec3(0.3, -0.2, -1.0));
}

}  // namespace
}  // namespace carom
