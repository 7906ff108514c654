// drop_cells_out_of_reach: see reach_cells.hpp.
#include "events/event_driven/reach_cells.hpp"

#include <algorithm>
#include <cassert>

namespace carom {

namespace {
/// drop_cells_out_of_reach for a block of (2 kReach + 1)^3 cells (loops unrolled).
template <int kReach>
int drop_out_of_reach(std::int32_t* cells, const double (&slab)[3][7], const double* bound,
                      double reach_at_rest, double reach_per_speed) {
  constexpr int kWidth = 2 * kReach + 1;
  int kept = 0, c = 0;
  for (int z = 0; z < kWidth; ++z)
    for (int y = 0; y < kWidth; ++y)
      for (int x = 0; x < kWidth; ++x, ++c) {
        const std::int32_t cell = cells[c];
        const double reach = reach_at_rest + reach_per_speed * bound[cell];
        const double distance2 = slab[0][x] + slab[1][y] + slab[2][z];
        cells[kept] = cell;
        kept += !(distance2 > reach * reach);
      }
  return kept;
}
}  // namespace

int drop_cells_out_of_reach(const HierarchicalGrid& grid, std::int32_t i, const ReachQuery& query,
                            double earliest_clock, std::int32_t* cells,
                            [[maybe_unused]] int count) {
  // A candidate b in cell C fails may_reach when the distance of the stored positions exceeds
  // (r_i + r_b + sweep_i + sweep_b)(1 + 1e-12), sweep_b = reach_bound(v_b, end - clock_b). Over
  // C's particles that sum is at most R(V) = r_i + r_max + sweep_i + reach_bound_at_speed(V,
  // end - t0) with the level's largest radius r_max, C's speed bound V and the earliest clock
  // t0: in exact arithmetic R(V) = A + B V (A = r_i + r_max + sweep_i + s^2 drive / 2,
  // B = s (1 + s rate / 2), s = end - t0), taken here 1e-9 larger, far above the round-off of
  // either evaluation. The distance is at least the distance from i's position to C's box, less
  // a margin for stored positions that lie on C's faces up to round-off. Where the block wraps,
  // that is the distance to the nearest image: along a periodic axis of n >= 2m + 2 cells (the
  // grid's least) a cell at offset |d| <= m lies within (|d| + 1) cell widths, its other images
  // at least n - |d| - 1 >= m + 1 widths away. A cell beyond R(V) holds no candidate that the
  // reach test would pass (debug builds check every one), so the same candidates reach
  // relax_pair_time in the same order.
  constexpr double kFaceMargin = 1e-9;  // of a cell width: far above any position's round-off
  constexpr double kWiden = 1.0 + 1e-9;
  const int level = grid.level_of(i);
  const HierarchicalGrid::Level& cell_level = grid.levels()[level];
  const int m = cell_level.reach;
  assert(count == (2 * m + 1) * (2 * m + 1) * (2 * m + 1));
  // The squared gap from i's position to the slab of cells at offset d along each axis.
  const Vec3 lower = grid.cell_lower(i), upper = grid.cell_upper(i);
  double slab[3][7];
  static_assert(2 * HierarchicalGrid::kMaxSubdivision + 1 <= 7);
  for (int k = 0; k < 3; ++k) {
    const double h = cell_level.cell_size[k], margin = kFaceMargin * h;
    const double below = query.position[k] - lower[k] - margin;
    const double above = upper[k] - query.position[k] - margin;
    for (int d = 1; d <= m; ++d) {
      const double gap_below = std::max(0.0, below + (d - 1) * h);
      const double gap_above = std::max(0.0, above + (d - 1) * h);
      slab[k][m - d] = gap_below * gap_below;
      slab[k][m + d] = gap_above * gap_above;
    }
    slab[k][m] = 0.0;
  }
  const double span = query.end - earliest_clock;
  const double reach_at_rest = (query.radius + cell_level.max_radius + query.sweep +
                                0.5 * span * span * query.bounds.drive) *
                               kWiden;
  const double reach_per_speed = span * (1.0 + 0.5 * span * query.bounds.rate) * kWiden;
  const double* bound = grid.cell_bound_array(level);
  switch (m) {
    case 1:
      return drop_out_of_reach<1>(cells, slab, bound, reach_at_rest, reach_per_speed);
    case 2:
      return drop_out_of_reach<2>(cells, slab, bound, reach_at_rest, reach_per_speed);
    default:
      return drop_out_of_reach<3>(cells, slab, bound, reach_at_rest, reach_per_speed);
  }
}

}  // namespace carom
