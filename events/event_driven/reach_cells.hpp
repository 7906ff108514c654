#pragma once
/// Which cells of a relax prediction's block can hold a partner at all.
///
/// A relax prediction walks the (2m+1)^3 cells around its particle and ends most candidates
/// with the reach test (may_reach, pair_batch.hpp): their stored positions are farther apart
/// than the two radii and how far each can fly before the prediction's end. Where cells are
/// wide against the particle (fines among large spheres), whole cells lie beyond that reach:
/// the distance to the cell's box exceeds the particle's radius and sweep plus the level's
/// largest radius and the sweep of the fastest particle there. The grid keeps each cell's
/// largest speed (HierarchicalGrid::raise_cell_bound, with RelaxFlightBounds::speed_bound);
/// those cells are then dropped before the walk. A dropped cell holds no particle that the
/// reach test would pass, so the prediction finds the same candidates in the same order and
/// the same event, bit for bit (tests/test_reach_cells.cpp checks every dropped cell against
/// may_reach). In the main job it ends about 30 % of the candidates before they are loaded.
#include <cstdint>

#include "core/cell_grid.hpp"
#include "events/event_driven/pair_batch.hpp"

namespace carom {

/// Removes from `cells` (particle i's own-level block as own_block wrote it: count cells, z
/// then y then x) the cells whose particles all fail may_reach(query, ...), given that every
/// particle's stored clock is at least `earliest_clock` (s), each cell's bound in `grid` is at
/// least the speed_bound of its particles' stored velocities, and stored positions lie in their
/// cells (up to round-off). The kept cells stay in their order; returns how many.
int drop_cells_out_of_reach(const HierarchicalGrid& grid, std::int32_t i, const ReachQuery& query,
                            double earliest_clock, std::int32_t* cells, int count);

}  // namespace carom
