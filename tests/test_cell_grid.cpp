// HierarchicalGrid::for_each_candidate (core/cell_grid.hpp) against an all-pairs O(N^2) oracle.
//
// Required: while i stays in its cell and every j stays in its own cell, any j that could touch i
// must be visited. That is every j whose cell box comes within a_i + a_j of i's cell box
// (minimum over periodic images), because j's centre is somewhere in its cell and i's centre
// somewhere in i's. The oracle computes that box-box distance exactly and asks the grid for a
// superset (it may visit more), with no particle visited twice and never i itself.
// The criterion uses a margin of 1e-9 of the contact distance so that exact ties on cell faces
// (a measure-zero set that round-off decides either way) cannot make the test flaky.
#include <gtest/gtest.h>

#include <cctype>

#include <cmath>
#include <set>

#include "core/cell_grid.hpp"
#include "core/rng.hpp"

namespace carom {
namespace {

double interval_gap(double lo1, double hi1, double lo2, double hi2) {
  return std::max(0.0, std::max(lo1 - hi2, lo2 - hi1));
}

/// Per axis, the gap between the cells of i and j (the nearest periodic image).
Vec3 box_gap_per_axis(const HierarchicalGrid& grid, std::int32_t i, std::int32_t j) {
  const Domain& d = grid.domain();
  const Vec3 li = grid.cell_lower(i), ui = grid.cell_upper(i), lj = grid.cell_lower(j), uj = grid.cell_upper(j);
  Vec3 gaps;
  for (int k = 0; k < 3; ++k) {
    double gap = interval_gap(li[k], ui[k], lj[k], uj[k]);
    if (d.periodic[k]) {
      const double L = d.length()[k];
      gap = std::min({gap, interval_gap(li[k], ui[k], lj[k] + L, uj[k] + L),
                      interval_gap(li[k], ui[k], lj[k] - L, uj[k] - L)});
    }
    gaps[k] = gap;
  }
  return gaps;
}

double box_distance(const HierarchicalGrid& grid, std::int32_t i, std::int32_t j) {
  return box_gap_per_axis(grid, i, j).norm();
}

struct GridCase {
  const char* name;
  std::vector<double> diameters;  // drawn uniformly per particle
  Vec3 length;
  std::array<bool, 3> periodic;
  int count;
  double level_ratio;
  int subdivision = 1;  // 0: the cost model picks each level's cells (widened ones included)
};
/// How ctest lists a case (instead of its bytes).
void PrintTo(const GridCase& c, std::ostream* out) { *out << c.name; }

class GridOracle : public ::testing::TestWithParam<GridCase> {};

/// 95 % fines of a tenth of the diameter by number: the cost model widens the fines' cells.
const std::vector<double> kFinesRich = {1.0, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1,
                                        0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1};

/// The case's grid with its particles placed at random (radii into `radius`).
HierarchicalGrid filled_grid(const GridCase& c, std::vector<double>& radius) {
  Rng rng(77);
  Domain domain;
  domain.lower = Vec3(-1.0, 0.5, 2.0);
  domain.upper = domain.lower + c.length;
  domain.periodic = c.periodic;
  radius.assign(c.count, 0.0);
  std::vector<Vec3> position(c.count);
  for (int i = 0; i < c.count; ++i) {
    radius[i] = 0.5 * c.diameters[rng.below(c.diameters.size())];
    for (int k = 0; k < 3; ++k) position[i][k] = domain.lower[k] + rng.uniform() * c.length[k];
  }
  HierarchicalGrid grid(domain, radius, c.level_ratio, c.subdivision);
  for (int i = 0; i < c.count; ++i) grid.insert(i, position[i]);
  return grid;
}

TEST_P(GridOracle, VisitsEveryPossiblePartnerOnce) {
  const GridCase& c = GetParam();
  std::vector<double> radius;
  const HierarchicalGrid grid = filled_grid(c, radius);
  long required = 0, visited_total = 0;
  for (std::int32_t i = 0; i < c.count; ++i) {
    std::vector<int> seen(c.count, 0);
    grid.for_each_candidate(i, [&](std::int32_t j) {
      ASSERT_NE(j, i) << "a particle is its own candidate";
      ++seen[j];
      ++visited_total;
    });
    for (std::int32_t j = 0; j < c.count; ++j) {
      ASSERT_LE(seen[j], 1) << c.name << ": particle " << j << " visited twice from " << i;
      if (j == i) continue;
      const double contact = radius[i] + radius[j];
      if (box_distance(grid, i, j) < contact * (1.0 - 1e-9)) {
        ++required;
        ASSERT_EQ(seen[j], 1) << c.name << ": missed partner " << j << " (a=" << radius[j] << ", level "
                              << grid.level_of(j) << ") of " << i << " (a=" << radius[i] << ", level "
                              << grid.level_of(i) << "), cell distance " << box_distance(grid, i, j)
                              << " < contact " << contact;
      }
    }
  }
  EXPECT_GT(required, c.count) << "the case must exercise many required pairs";
  // The hierarchy must also be worth having: far fewer visits than all pairs.
  EXPECT_LT(visited_total, 0.5 * double(c.count) * c.count);
}

// A crossing searches the other levels only in the cells that came into its reach, so a pair on
// two levels whose cells came within reach of each other when one of them crossed is found by
// that one alone: j must be among i's candidates exactly when i is among j's, whatever their
// radii within their levels. (Grown by each particle's own radius, a small particle of a
// polydisperse level reached fewer cells than the large ones of the other level reached back,
// and runs missed collisions: GridLevelsRun.PolydisperseLevelsMatchOneGrid.)
TEST_P(GridOracle, OtherLevelsSeeEachOtherBothWays) {
  const GridCase& c = GetParam();
  std::vector<double> radius;
  const HierarchicalGrid grid = filled_grid(c, radius);
  std::vector<std::set<std::int32_t>> seen(c.count);
  for (std::int32_t i = 0; i < c.count; ++i)
    grid.for_each_candidate_on_other_levels(i, [&](std::int32_t j) { seen[i].insert(j); });
  long pairs = 0;
  for (std::int32_t i = 0; i < c.count; ++i)
    for (const std::int32_t j : seen[i]) {
      ASSERT_NE(grid.level_of(i), grid.level_of(j)) << c.name;
      ++pairs;
      if (seen[j].count(i)) continue;
      // Where the levels' cells line up, a cell may lie exactly the reach away, and round-off
      // decides each side: touching takes both centres on the cells' faces, a set of measure
      // zero (as in VisitsEveryPossiblePartnerOnce).
      const double reach = grid.reach_between(grid.level_of(i), grid.level_of(j));
      const double gap = box_gap_per_axis(grid, i, j).maxCoeff();
      ASSERT_NEAR(gap, reach, 1e-9 * reach)
          << c.name << ": " << j << " (a=" << radius[j] << ", level " << grid.level_of(j)
          << ") is a candidate of " << i << " (a=" << radius[i] << ", level " << grid.level_of(i)
          << ") but not the other way round";
    }
  if (grid.levels().size() > 1) {
    EXPECT_GT(pairs, c.count) << "the case must exercise many pairs";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Polydisperse, GridOracle,
    ::testing::Values(
        GridCase{"ratio 1:2 periodic", {1.0, 0.5}, Vec3(12, 10, 11), {true, true, true}, 3000, 0.5},
        GridCase{
            "ratio 1:5 walled", {1.0, 0.2}, Vec3(12, 10, 11), {false, false, false}, 3000, 0.5},
        GridCase{"ratio 1:10 mixed axes",
                 {1.0, 0.1},
                 Vec3(9.3, 8.1, 7.7),
                 {true, false, true},
                 4000,
                 0.5},
        GridCase{"three sizes",
                 {1.0, 0.45, 0.1, 0.07},
                 Vec3(10.5, 9.2, 8.8),
                 {false, true, false},
                 4000,
                 0.5},
        GridCase{"1:10 one grid", {1.0, 0.1}, Vec3(9, 9, 9), {true, true, true}, 2000, 0.0},
        GridCase{"1:10 fine level ratio",
                 {1.0, 0.1, 0.3},
                 Vec3(9, 9, 9),
                 {true, true, false},
                 3000,
                 0.9},
        GridCase{
            "four cells per axis", {1.0, 0.2}, Vec3(4.3, 4.9, 4.1), {true, true, true}, 600, 0.5},
        GridCase{"1:10 fines widened cells",
                 kFinesRich,
                 Vec3(6.1, 5.7, 6.4),
                 {true, false, true},
                 6000,
                 -1.0,
                 0},
        GridCase{"1:5 fines cost model",
                 {1.0, 0.2, 0.2, 0.2},
                 Vec3(7.1, 6.7, 6.4),
                 {false, true, true},
                 4000,
                 -1.0,
                 0}),
    // The case's description as a test name (letters and digits; everything else an underscore).
    [](const ::testing::TestParamInfo<GridCase>& info) {
      std::string name = info.param.name;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

// Moving a particle across faces (with periodic wraps) keeps it findable and its shift right.
// A point far outside the box (a listed particle before the placement checks it against the
// walls) lands in the nearest edge cell: the cell index is clamped before it is converted to an
// int, which overflowed for 2.4e7 m in a 3 cm box (found by fuzzing; UBSan flags the overflow).
TEST(GridCrossing, PointsFarOutsideTheBoxLandInTheEdgeCells) {
  Domain domain;
  domain.upper = Vec3(0.03, 0.02, 0.03);
  HierarchicalGrid grid(domain, {0.001, 0.001}, 0.5);
  grid.insert(0, Vec3(2.4e7, -1e300, 0.015));
  grid.insert(1, Vec3(-2.4e7, 1e300, 0.015));
  const std::array<int, 3>& cells = grid.levels()[0].cells;
  EXPECT_EQ(grid.cell_of(0)[0], cells[0] - 1);
  EXPECT_EQ(grid.cell_of(0)[1], 0);
  EXPECT_EQ(grid.cell_of(1)[0], 0);
  EXPECT_EQ(grid.cell_of(1)[1], cells[1] - 1);
}

TEST(GridCrossing, CrossingFacesWrapsPeriodicAxes) {
  Domain domain;
  domain.upper = Vec3(4, 5, 6);
  domain.periodic = {true, false, true};
  HierarchicalGrid grid(domain, {0.5, 0.5}, 0.5);
  grid.insert(0, Vec3(0.1, 0.1, 5.9));
  grid.insert(1, Vec3(3.9, 0.1, 0.1));
  // 0 and 1 are neighbours through the x and z boundaries.
  int found = 0;
  grid.for_each_candidate(0, [&](std::int32_t j) { found += j == 1; });
  EXPECT_EQ(found, 1);
  const Vec3 shift = grid.cross(0, 0, -1);  // leave through x = 0
  EXPECT_EQ(shift, Vec3(4, 0, 0));
  EXPECT_EQ(grid.cell_of(0)[0], grid.levels()[0].cells[0] - 1);
  const Vec3 shift_z = grid.cross(0, 2, +1);  // leave through z = 6
  EXPECT_EQ(shift_z, Vec3(0, 0, -6));
  EXPECT_EQ(grid.cell_of(0)[2], 0);
  EXPECT_TRUE(grid.is_outer_face(0, 1, -1));
  EXPECT_FALSE(grid.is_outer_face(0, 0, -1));
}

// The crossing's hint (prefetch_entering_slab) loads the cells at cell_across + slab_offsets:
// they must be the cells own_slab hands the crossing's scan once the particle has crossed, at
// the box's periodic faces too. Checked by crossing for real, both ways on every open face; the
// test fails when cell_across forgets the periodic wrap or steps the wrong way.
TEST(GridCrossing, CellAcrossIsTheCellAfterTheCrossing) {
  Domain domain;
  domain.upper = Vec3(5.3, 4.1, 6.2);
  domain.periodic = {true, false, true};
  HierarchicalGrid grid(domain, std::vector<double>(400, 0.5), 0.0);
  Rng rng(11);
  for (std::int32_t i = 0; i < 400; ++i) {
    Vec3 r;
    for (int k = 0; k < 3; ++k) r[k] = rng.uniform() * domain.length()[k];
    grid.insert(i, r);
  }
  long checked = 0, wrapped = 0;
  for (std::int32_t i = 0; i < 400; ++i)
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2, direction = (face % 2) ? +1 : -1;
      if (grid.is_outer_face(i, axis, direction)) continue;
      const std::int32_t across = grid.cell_across(i, face);
      const Vec3 shift = grid.cross(i, axis, direction);
      std::int32_t cells[HierarchicalGrid::kMaxBlock];
      bool wraps = false;
      const int count = grid.own_slab(i, axis, direction, cells, wraps);
      const std::vector<std::int32_t>& offsets = grid.levels()[0].slab_offsets[face];
      ASSERT_EQ(count, static_cast<int>(offsets.size()));
      for (int k = 0; k < count; ++k)
        ASSERT_EQ(across + offsets[k], cells[k]) << "particle " << i << " face " << face;
      ++checked;
      wrapped += shift != Vec3::Zero();
      grid.cross(i, axis, -direction);
    }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(wrapped, 0);
}

// The cost model's cells (HierarchicalGrid::cheapest_levels): fines 1:10 that are 99 % of the
// particles move 32 times as fast as the large ones at one temperature and cross cells all the
// time; their cells are widened beyond their diameter (fewer crossings, and fewer cells for the
// large particles to visit). A monodisperse fluid keeps one cell per diameter.
TEST(GridLevels, CostModelWidensTheCellsOfFastFines) {
  Domain domain;
  domain.upper = Vec3::Constant(12.42);
  domain.periodic = {true, true, true};
  std::vector<double> radius(100000, 0.05);
  std::fill(radius.begin(), radius.begin() + 1000, 0.5);
  const HierarchicalGrid fines(domain, radius, -1.0, 0);
  ASSERT_EQ(fines.levels().size(), 2u);
  EXPECT_GE(fines.levels()[1].cell_size.x(), 1.5 * 0.1);
  EXPECT_EQ(fines.levels()[1].reach, 1);
  domain.upper = Vec3::Constant(34.73);
  const HierarchicalGrid mono(domain, std::vector<double>(32000, 0.5), -1.0, 0);
  ASSERT_EQ(mono.levels().size(), 1u);
  EXPECT_EQ(mono.levels()[0].reach, 1);
  EXPECT_LT(mono.levels()[0].cell_size.x(), 1.05);
}

// A fines-rich grid with particles in it, for the tests of the other levels' cells below.
struct FinesGrid {
  Domain domain;
  std::vector<double> radius;
  HierarchicalGrid grid;
  explicit FinesGrid(std::array<bool, 3> periodic) {
    Rng rng(7);
    domain.lower = Vec3(-1.0, 0.5, 2.0);
    domain.upper = domain.lower + Vec3(6.3, 5.9, 6.6);
    domain.periodic = periodic;
    for (int i = 0; i < 5000; ++i) radius.push_back(0.5 * kFinesRich[rng.below(kFinesRich.size())]);
    grid = HierarchicalGrid(domain, radius, -1.0, 0);
    for (int i = 0; i < 5000; ++i) {
      Vec3 r;
      for (int k = 0; k < 3; ++k) r[k] = domain.lower[k] + rng.uniform() * domain.length()[k];
      grid.insert(i, r);
    }
  }
  /// The cells of `level` that for_each_covering_piece (or, with a direction,
  /// for_each_entering_piece) hands over.
  std::vector<std::int32_t> pieces(std::int32_t i, int level, int axis = 0,
                                   int direction = 0) const {
    std::vector<std::int32_t> cells;
    auto take = [&](const std::int32_t* c, int count, bool) {
      EXPECT_LE(count, HierarchicalGrid::kMaxBlock);
      cells.insert(cells.end(), c, c + count);
    };
    if (direction == 0)
      grid.for_each_covering_piece(i, level, take);
    else
      grid.for_each_entering_piece(i, level, axis, direction, take);
    return cells;
  }
};

// The batched scan of the other levels walks the lists of the cells for_each_covering_piece
// hands over: the same candidates, in the same order, as the visitor of one candidate at a time
// (the order decides which of equal contact times wins).
TEST(GridLevels, CoveringPiecesHoldTheOtherLevelsCandidatesInOrder) {
  for (const auto periodic :
       {std::array<bool, 3>{true, false, true}, std::array<bool, 3>{true, true, true}}) {
    const FinesGrid f(periodic);
    ASSERT_EQ(f.grid.levels().size(), 2u);
    for (std::int32_t i = 0; i < 5000; i += 7) {
      std::vector<std::int32_t> expected, walked;
      f.grid.for_each_candidate_on_other_levels(i,
                                                [&](std::int32_t j) { expected.push_back(j); });
      const int other = 1 - f.grid.level_of(i);
      for (const std::int32_t cell : f.pieces(i, other))
        for (std::int32_t j = f.grid.head(other, cell); j >= 0; j = f.grid.next(j))
          walked.push_back(j);
      ASSERT_EQ(walked, expected) << "particle " << i;
    }
  }
}

// After a crossing the other levels are searched only in the cells that came into reach: with
// the cells covered from the cell the particle came from, they hold every cell covered from its
// new cell, and none of them was covered before (or, after a periodic wrap, every cell).
TEST(GridLevels, EnteringPiecesAreTheCellsThatCameIntoReach) {
  FinesGrid f({true, false, true});
  long entered = 0, wrapped = 0;
  for (std::int32_t i = 0; i < 5000; i += 11) {
    const int other = 1 - f.grid.level_of(i);
    for (int axis = 0; axis < 3; ++axis)
      for (int direction : {-1, 1}) {
        if (f.grid.is_outer_face(i, axis, direction)) continue;
        const std::vector<std::int32_t> before = f.pieces(i, other);
        const Vec3 shift = f.grid.cross(i, axis, direction);
        const std::vector<std::int32_t> after = f.pieces(i, other);
        const std::vector<std::int32_t> entering = f.pieces(i, other, axis, direction);
        const std::set<std::int32_t> old_cells(before.begin(), before.end()),
            new_cells(after.begin(), after.end()), band(entering.begin(), entering.end());
        if (shift != Vec3::Zero()) {
          EXPECT_EQ(band, new_cells);
          ++wrapped;
        } else {
          for (const std::int32_t c : new_cells)
            ASSERT_TRUE(old_cells.count(c) || band.count(c))
                << "cell " << c << " of particle " << i << " never searched";
          for (const std::int32_t c : band) {
            ASSERT_TRUE(new_cells.count(c)) << "cell " << c << " out of reach";
            ASSERT_FALSE(old_cells.count(c)) << "cell " << c << " searched twice";
          }
          entered += static_cast<long>(band.size());
        }
        f.grid.cross(i, axis, -direction);
      }
  }
  EXPECT_GT(entered, 0);
  EXPECT_GT(wrapped, 0);
}

// for_each_covering_piece_near against the cells' boxes: it hands over covering cells only,
// each once; every cell whose box comes within the reach of the point (the nearest periodic
// image; an edge cell of a walled axis reaches to infinity) among them; with no bound, every
// covering cell; and the cells within the first reach before the others.
TEST(GridLevels, NearPiecesHoldEveryCellWithinReach) {
  for (const auto periodic :
       {std::array<bool, 3>{true, false, true}, std::array<bool, 3>{true, true, true}}) {
    const FinesGrid f(periodic);
    const HierarchicalGrid& grid = f.grid;
    Rng rng(3);
    long near_total = 0, covering_total = 0;
    for (std::int32_t i = 0; i < 5000; ++i) {
      if (grid.level_of(i) != 0) continue;
      const int other = 1;
      const Vec3 lower = grid.cell_lower(i), upper = grid.cell_upper(i);
      Vec3 p;
      for (int k = 0; k < 3; ++k) p[k] = lower[k] + rng.uniform() * (upper[k] - lower[k]);
      // The distance from p to particle j's cell box.
      auto distance = [&](std::int32_t j) {
        const Vec3 lo = grid.cell_lower(j), hi = grid.cell_upper(j);
        const auto& level = grid.levels()[other];
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) {
          double gap = kNever;
          for (const double shift : {-1.0, 0.0, 1.0}) {
            if (shift != 0.0 && !periodic[k]) continue;
            const double L = shift * f.domain.length()[k];
            double l = lo[k] + L, h = hi[k] + L;
            if (!periodic[k] && grid.cell_of(j)[k] == 0) l = -kNever;
            if (!periodic[k] && grid.cell_of(j)[k] == level.cells[k] - 1) h = kNever;
            gap = std::min(gap, interval_gap(p[k], p[k], l, h));
          }
          sum += gap * gap;
        }
        return std::sqrt(sum);
      };
      const std::vector<std::int32_t> covering_cells = f.pieces(i, other);
      const std::set<std::int32_t> covering(covering_cells.begin(), covering_cells.end());
      covering_total += static_cast<long>(covering_cells.size());
      for (const double reach : {0.0, 0.3, 0.6, kNever}) {
        std::vector<std::int32_t> cells, visited;
        grid.for_each_covering_piece_near(
            i, other, p, 0.55, [&] { return reach; },
            [&](const std::int32_t* c, int count, bool) {
              EXPECT_LE(count, HierarchicalGrid::kNearPiece);
              cells.insert(cells.end(), c, c + count);
            });
        const std::set<std::int32_t> handed(cells.begin(), cells.end());
        ASSERT_EQ(handed.size(), cells.size()) << "a cell handed over twice, particle " << i;
        for (const std::int32_t c : cells) {
          ASSERT_TRUE(covering.count(c)) << "cell " << c << " does not cover particle " << i;
          for (std::int32_t j = grid.head(other, c); j >= 0; j = grid.next(j)) visited.push_back(j);
        }
        if (reach == kNever) {
          EXPECT_EQ(handed, covering) << "particle " << i;
        } else {
          near_total += static_cast<long>(cells.size());
        }
        const std::set<std::int32_t> seen(visited.begin(), visited.end());
        for (const std::int32_t c : covering_cells)
          for (std::int32_t j = grid.head(other, c); j >= 0; j = grid.next(j)) {
            if (distance(j) <= reach * (1.0 - 1e-12)) {
              ASSERT_TRUE(seen.count(j)) << "particle " << j << " at " << distance(j)
                                         << " of particle " << i << " skipped, reach " << reach;
            }
          }
        // The cells within the first reach come first.
        const double first = std::min(0.55, reach);
        bool beyond = false;
        for (const std::int32_t j : visited) {
          if (distance(j) > first * (1.0 + 1e-12)) beyond = true;
          if (beyond) {
            ASSERT_FALSE(distance(j) < first * (1.0 - 1e-12))
                << "particle " << j << " of the first pass came late, particle " << i;
          }
        }
      }
    }
    // Three reaches out of four skip cells: fewer than three walks over every covering cell.
    EXPECT_LT(near_total, 2 * covering_total);
    EXPECT_GT(covering_total, 0);
  }
}

// Particles beyond a walled face sit in the edge cells: a fine there is within reach of a large
// particle beyond the same face even where the edge cell's box, taken at its face, is not.
TEST(GridLevels, NearPiecesReachBeyondTheWalls) {
  Domain domain;
  domain.upper = Vec3(8, 8, 8);
  domain.periodic = {true, false, true};
  HierarchicalGrid grid(domain, {0.5, 0.05}, 0.5);
  ASSERT_EQ(grid.levels().size(), 2u);
  grid.insert(0, Vec3(4.0, -0.8, 4.0));
  grid.insert(1, Vec3(4.0, -1.3, 4.0));  // 0.5 below: within 0.6, the edge cell 0.8 away
  std::vector<std::int32_t> cells;
  grid.for_each_covering_piece_near(
      0, 1, Vec3(4.0, -0.8, 4.0), 0.55, [] { return 0.6; },
      [&](const std::int32_t* c, int count, bool) { cells.insert(cells.end(), c, c + count); });
  int found = 0;
  for (const std::int32_t c : cells)
    for (std::int32_t j = grid.head(1, c); j >= 0; j = grid.next(j)) found += j == 1;
  EXPECT_EQ(found, 1);
}

}  // namespace
}  // namespace carom
