// drop_cells_out_of_reach (events/event_driven/reach_cells.hpp): a relax prediction drops the
// cells of its block that hold no particle it could reach, from each cell's speed bound.
//
// The oracle is the reach test itself: every particle of every dropped cell must fail
// may_reach, which is what the prediction would have decided for it one at a time, so the
// prediction sees the same candidates in the same order. Cases: fines among large spheres in
// one grid (the main job's mixture, where cells are wide against the fines), walled and
// periodic boxes (the halo cells of a periodic axis must carry their image's bound), a periodic
// box only four cells wide with fast particles (another image may come within reach), finer
// subdivisions (blocks of 5^3 and 7^3 cells), and particles placed exactly on cell faces (the
// stored state after a crossing). Each case must drop a real share of the candidates, so that
// the oracle is exercised. The engine runs a bidisperse gas under drag with and without the
// drop: the same run bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/cell_grid.hpp"
#include "core/relax_flight.hpp"
#include "core/rng.hpp"
#include "events/event_driven/engine.hpp"
#include "events/event_driven/pair_batch.hpp"
#include "events/event_driven/reach_cells.hpp"
#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

struct ReachCase {
  const char* name;
  int count;
  Vec3 length;           // box edges, in large diameters (d = 1)
  bool periodic;         // x and y periodic, z walled
  int subdivision;       // grid cells per diameter
  double speed;          // typical speed (per axis), m/s
  double horizon;        // the predictions' span beyond the latest clock, s
  double least_dropped;  // the share of candidates the case must drop at least
};
void PrintTo(const ReachCase& c, std::ostream* out) {
  *out << c.name;
}

class ReachCellsDrop : public ::testing::TestWithParam<ReachCase> {};

TEST_P(ReachCellsDrop, DroppedCellsHoldNoParticleTheReachTestPasses) {
  const ReachCase& c = GetParam();
  Domain domain;
  domain.lower = Vec3(-1.0, 2.0, 0.5);  // off the origin: positions carry round-off
  domain.upper = domain.lower + c.length;
  domain.periodic = {c.periodic, c.periodic, false};
  // A quarter large spheres (d = 1), the rest fines of d = 1/3, all in one grid.
  std::vector<double> radius(c.count, 0.5 / 3.0);
  for (int i = 0; i < c.count; i += 4) radius[i] = 0.5;
  HierarchicalGrid grid(domain, radius, /*level_ratio=*/0.0, c.subdivision);
  ASSERT_EQ(grid.levels().size(), 1u);
  Rng rng(29);
  const double t0 = 1.0, now = 1.0 + c.horizon;
  RelaxFlightBounds bounds;
  bounds.drive = 30.0;
  bounds.rate = 50.0;
  std::vector<PairState> records(c.count);
  for (std::int32_t i = 0; i < c.count; ++i) {
    PairState& r = records[i];
    for (int k = 0; k < 3; ++k) r.position[k] = domain.lower[k] + c.length[k] * rng.uniform();
    grid.insert(i, r.position);
    if (i % 7 == 0) {  // on a face of its cell, as after a crossing
      const int k = i % 3;
      r.position[k] = (i % 2 ? grid.cell_upper(i) : grid.cell_lower(i))[k];
    }
    // Speeds spread over two decades, some particles much faster than the rest.
    const double scale = c.speed * (i % 11 == 0 ? 10.0 : rng.uniform(0.1, 1.0));
    for (int k = 0; k < 3; ++k) r.velocity[k] = scale * rng.uniform(-1.0, 1.0);
    r.clock = t0 + (now - t0) * rng.uniform();
    r.radius = radius[i];
    grid.raise_cell_bound(i, RelaxFlightBounds::speed_bound(r.velocity));
  }
  std::size_t candidates = 0, dropped = 0, cells_dropped = 0;
  for (std::int32_t i = 0; i < c.count; ++i) {
    const PairState& a = records[i];
    // As relax_collision asks: up to the prediction's end, the query's own reach bound.
    ReachQuery query{a.position, a.radius, 0.0, 0.0, bounds, domain};
    query.end = now + c.horizon * rng.uniform();
    query.sweep = bounds.reach_bound(a.velocity, query.end - a.clock);
    std::int32_t block[HierarchicalGrid::kMaxBlock], kept[HierarchicalGrid::kMaxBlock];
    bool wrapped = false;
    const int count = grid.own_block(i, block, wrapped);
    std::copy(block, block + count, kept);
    const int left = drop_cells_out_of_reach(grid, i, query, t0, kept, count);
    ASSERT_LE(left, count);
    // The kept cells in the block's order, and every particle of the others out of reach.
    int k = 0;
    for (int b = 0; b < count; ++b) {
      const bool is_kept = k < left && kept[k] == block[b];
      k += is_kept;
      for (std::int32_t j = grid.head(0, block[b]); j >= 0; j = grid.next(j)) {
        if (j == i) continue;
        ++candidates;
        if (is_kept) continue;
        ++dropped;
        const bool reached =
            wrapped ? may_reach<true>(query, records[j]) : may_reach<false>(query, records[j]);
        ASSERT_FALSE(reached) << "particle " << j << " (radius " << records[j].radius
                              << ") in a dropped cell of particle " << i << "'s block passes "
                              << "the reach test";
      }
      cells_dropped += !is_kept;
    }
    ASSERT_EQ(k, left) << "the kept cells are not the block's cells in order";
  }
  std::printf("%s: %zu of %zu candidates dropped (%zu cells)\n", c.name, dropped, candidates,
              cells_dropped);
  EXPECT_GE(static_cast<double>(dropped), c.least_dropped * static_cast<double>(candidates))
      << "the case must drop cells for the oracle to check anything";
}

INSTANTIATE_TEST_SUITE_P(
    Blocks, ReachCellsDrop,
    ::testing::Values(
        ReachCase{"Walled", 800, Vec3(8.0, 6.0, 7.0), false, 1, 1.0, 0.01, 0.2},
        ReachCase{"Periodic", 800, Vec3(8.0, 6.0, 7.0), true, 1, 1.0, 0.01, 0.2},
        // Four cells a periodic axis, sweeps of up to a cell: other images come near.
        ReachCase{"NarrowPeriodicFast", 300, Vec3(4.0, 4.0, 6.0), true, 1, 30.0, 0.01, 0.005},
        // Subdivided in a periodic box of 2m + 2 cells: a corner cell of the block can lie
        // farther than another image of its particles.
        ReachCase{"NarrowPeriodicSubdivided", 200, Vec3(3.0, 3.0, 6.0), true, 2, 3.0, 0.01, 0.05},
        ReachCase{"Subdivided2", 800, Vec3(8.0, 6.0, 7.0), true, 2, 1.0, 0.01, 0.2},
        ReachCase{"Subdivided3", 800, Vec3(8.0, 6.0, 7.0), true, 3, 1.0, 0.01, 0.2}),
    [](const ::testing::TestParamInfo<ReachCase>& info) { return std::string(info.param.name); });

// The bound of a cell near a periodic face is what its halo images hold: a block that wraps
// reads them there.
TEST(ReachCells, CellBoundsReachThePeriodicImages) {
  Domain domain;
  domain.upper = Vec3(5.0, 5.0, 5.0);
  domain.periodic = {true, true, true};
  const std::vector<double> radius(2, 0.5);
  HierarchicalGrid grid(domain, radius, 0.0, 1);
  grid.insert(0, Vec3(0.2, 0.2, 0.2));  // the corner cell: seven images in the halo
  grid.insert(1, Vec3(2.5, 2.5, 2.5));
  grid.raise_cell_bound(0, 3.0);
  grid.raise_cell_bound(0, 2.0);  // lower: no change
  grid.raise_cell_bound(1, 1.0);
  const double* bound = grid.cell_bound_array(0);
  // Particle 1's block (cells 1..3 on each axis) sees only its own cell raised.
  std::int32_t cells[HierarchicalGrid::kMaxBlock];
  bool wrapped = false;
  int count = grid.own_block(1, cells, wrapped);
  double sum = 0.0;
  for (int c = 0; c < count; ++c) sum += bound[cells[c]];
  EXPECT_EQ(sum, 1.0);
  EXPECT_EQ(bound[cells[13]], 1.0);  // the centre of the block
  // A particle in the opposite corner cell sees particle 0's cell through the halo, across
  // every periodic face: one of its block's cells holds 3.
  grid.insert(1, Vec3(4.8, 4.8, 4.8));
  count = grid.own_block(1, cells, wrapped);
  EXPECT_TRUE(wrapped);
  EXPECT_EQ(bound[cells[count - 1]], 3.0);  // offset (+1, +1, +1): cell (0, 0, 0)
  grid.clear_cell_bounds();
  for (int c = 0; c < count; ++c) EXPECT_EQ(bound[cells[c]], 0.0);
}

/// A bidisperse gas (600 particles, fines of a third of the large diameter, 85 % by number, in
/// one grid: cells of about four particles) under unequal drag, walls in z, periodic in x and y,
/// with the TC model (the bed that settles on the floor), run to `end` in pieces of 0.05 s,
/// after each of which `check` sees the engine.
template <class Check>
std::unique_ptr<EventDrivenEngine> run_relax_gas(bool drop, bool lines, double end, Check check) {
  GranularGasSpec spec;
  spec.count = 600;
  spec.volume_fraction = 0.3;
  spec.fines_diameter_ratio = 1.0 / 3.0;
  spec.fines_number_fraction = 0.85;
  spec.seed = 13;
  System system = make_granular_gas(spec);
  // Walls in z: the gas moved up by half a large diameter into a box one diameter taller.
  for (Vec3& r : system.particles.position) r.z() += 0.55;
  system.domain.upper.z() += 1.1;
  system.domain.periodic = {true, true, false};
  system.walls = box_walls(system.domain);
  system.flight.gravity = Vec3(0, 0, -1.0);
  system.materials = MaterialTable(system.species.size(), system.walls.size(),
                                   ContactLaw{0.9, 0.2, 0.3}, ContactLaw{0.9, 0.2, 0.3});
  EventDrivenOptions options;
  options.flight_model = FlightModel::Relax;
  options.grid_level_ratio = 0.0;  // one grid: the fines' cells are three of their diameters
  options.skip_unreachable_cells = drop;
  options.relax_pair_shortcuts = lines;
  options.threads = 1;
  options.collapse.contact_time = 1e-3;
  auto sim = std::make_unique<EventDrivenEngine>(system, options);
  Rng rng(5);
  sim->add_synchronising_action("fluid_step", 0.0, 0.02, [rng](GlobalStep& step) mutable {
    for (std::size_t i = 0; i < step.flights.size(); ++i) {
      // One particle in twenty in a fast jet: it speeds up after the step's reset of the
      // bounds and enters cells of slower particles (their bounds must be raised then).
      const double rate = 20.0 * rng.uniform(), jet = i % 20 == 0 ? 30.0 : 6.0;
      const Vec3 gas(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
      step.flights[i] = RelaxFlight{rate, Vec3(0, 0, -1.0) + rate * jet * gas};
    }
  });
  const int pieces = static_cast<int>(std::lround(end / 0.05));
  for (int k = 1; k <= pieces; ++k) {
    sim->run_until(0.05 * k);
    check(*sim);
  }
  return sim;
}

// The gas above for 2 s (about 5900 collisions; 20-35 s in the debug build): with the drop
// (the default) and without it the run is the same bit for bit, as the drop only spares the
// walk of cells whose particles the reach test would end; and every 0.05 s each particle's cell
// holds a speed bound at or above its speed (what the drop assumes; the debug build checks it
// at every prediction).
TEST(ReachCells, RelaxRunIsTheSameWithAndWithoutDroppingCells) {
  auto bounds_hold = [](const EventDrivenEngine& sim) {
    // Every particle's cell holds a speed bound at or above its stored speed (raised at every
    // collision and crossing, set at every fluid step).
    const HierarchicalGrid& grid = sim.grid();
    const ParticleStore& p = sim.system().particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const auto id = static_cast<std::int32_t>(i);
      std::int32_t cells[HierarchicalGrid::kMaxBlock];
      bool wrapped = false;
      const int count = grid.own_block(id, cells, wrapped);
      const double bound = grid.cell_bound_array(grid.level_of(id))[cells[count / 2]];
      EXPECT_GE(bound, RelaxFlightBounds::speed_bound(p.velocity[i]))
          << "particle " << i << " at t = " << sim.time();
    }
  };
  const auto plain = run_relax_gas(false, true, 2.0, bounds_hold);
  const auto dropping = run_relax_gas(true, true, 2.0, bounds_hold);
  ASSERT_GT(plain->statistics().pair_events, 4000u) << "the run must have collisions to compare";
  std::printf("pair collisions %llu, wall collisions %llu\n",
              static_cast<unsigned long long>(plain->statistics().pair_events),
              static_cast<unsigned long long>(plain->statistics().wall_events));
  // The drop is made on levels whose cells hold several particles (list_length_seen above 2.5,
  // kLongLists in relax_predictions.cpp): this gas must be one.
  EXPECT_GT(dropping->grid().list_length_seen(0), 3.0) << "the lists must be long for the drop";
  test::expect_same_runs(*dropping, *plain);
}

// The same gas for 1.5 s with the relax pair shortcuts (the default: the line test of the
// stored states, lines_apart, and the separating pairs, relax_pair_separating) and without them:
// the same run bit for bit, as they only end pairs that relax_pair_time's exact tests and
// contact search end too. (Their unit tests, in test_pair_batch.cpp and test_relax_roots.cpp,
// check that on random pairs; here they meet the collisions, contacts and crossings of a
// settling bed.)
TEST(ReachCells, RelaxRunIsTheSameWithAndWithoutThePairShortcuts) {
  auto nothing = [](const EventDrivenEngine&) {};
  // (Without the drop: the debug build's check of every dropped cell would double the time.)
  const auto plain = run_relax_gas(false, false, 1.5, nothing);
  const auto lines = run_relax_gas(false, true, 1.5, nothing);
  ASSERT_GT(plain->statistics().pair_events, 2000u) << "the run must have collisions to compare";
  test::expect_same_runs(*lines, *plain);
}

}  // namespace
}  // namespace carom
