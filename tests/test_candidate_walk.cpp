// gather_candidates (events/event_driven/pair_batch.hpp), the inner loop of every prediction,
// against a plain walk of the grid's lists (HierarchicalGrid::head and next, one particle at a
// time).
//
// The walk takes the first places of each cell's list without a branch (two, or four where the
// lists are long, reading past a list's end through next[-1] = -1) and the rest in a loop; the
// predictions consider what it hands over in that order, so it must hand over exactly the
// plain walk's candidates, in the same order, whatever the depth, with batches never over
// PairBatch::kCapacity. Cases: lists of about 15 (every own block more than a batch), of about
// one (most places past the end), and empty cells, in boxes walled and periodic (halo cells
// hold copies of the first particles), with particles taken out and put back as crossings do.
// The large systems' walk, with its loading hints, hands over the same.
// HierarchicalGrid::list_length_seen, which chooses the depth, is checked against a count of
// the particles per cell.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "core/cell_grid.hpp"
#include "core/rng.hpp"
#include "events/event_driven/pair_batch.hpp"

namespace carom {
namespace {

struct WalkCase {
  const char* name;
  int count;
  double length;  // box edge, in diameters (unit spheres)
  bool periodic;
};
void PrintTo(const WalkCase& c, std::ostream* out) {
  *out << c.name;
}

class CandidateWalk : public ::testing::TestWithParam<WalkCase> {};

/// The candidates of i's own block as a loop one particle at a time finds them.
std::vector<std::int32_t> plain_walk(const HierarchicalGrid& grid, std::int32_t i) {
  std::int32_t cells[HierarchicalGrid::kMaxBlock];
  bool wrapped = false;
  const int count = grid.own_block(i, cells, wrapped);
  const int level = grid.level_of(i);
  std::vector<std::int32_t> out;
  for (int c = 0; c < count; ++c)
    for (std::int32_t j = grid.head(level, cells[c]); j >= 0; j = grid.next(j))
      if (j != i) out.push_back(j);
  return out;
}

template <int kUnrolled, bool kPrefetch = false>
std::vector<std::int32_t> batched_walk(const HierarchicalGrid& grid, std::int32_t i,
                                       const std::vector<PairState>& records,
                                       const std::vector<std::uint32_t>& counters = {}) {
  std::int32_t cells[HierarchicalGrid::kMaxBlock];
  bool wrapped = false;
  const int count = grid.own_block(i, cells, wrapped);
  std::vector<std::int32_t> out;
  PairBatch batch;
  gather_candidates<kUnrolled, kPrefetch>(
      i, grid.head_array(grid.level_of(i)), grid.next_array(), cells, count, records.data(), batch,
      [&](int found) {
        EXPECT_GT(found, 0);
        EXPECT_LE(found, PairBatch::kCapacity);
        for (int k = 0; k < found; ++k)
          out.push_back(static_cast<std::int32_t>(batch.state[k] - records.data()));
      },
      counters.data());
  return out;
}

TEST_P(CandidateWalk, HandsOverThePlainWalksCandidatesInOrder) {
  const WalkCase& c = GetParam();
  Domain domain;
  domain.lower = Vec3::Zero();
  domain.upper = Vec3::Constant(c.length);
  domain.periodic = {c.periodic, false, c.periodic};
  const std::vector<double> radius(c.count, 0.5);
  HierarchicalGrid grid(domain, radius);
  Rng rng(17);
  std::vector<Vec3> position(c.count);
  for (std::int32_t i = 0; i < c.count; ++i) {
    for (int k = 0; k < 3; ++k) position[i][k] = c.length * rng.uniform();
    grid.insert(i, position[i]);
  }
  const std::vector<PairState> records(c.count);
  const std::vector<std::uint32_t> counters(c.count);
  std::size_t longest = 0, handed = 0;
  for (int round = 0; round < 2; ++round) {
    for (std::int32_t i = 0; i < c.count; ++i) {
      const std::vector<std::int32_t> expected = plain_walk(grid, i);
      longest = std::max(longest, expected.size());
      handed += expected.size();
      EXPECT_EQ(batched_walk<1>(grid, i, records), expected) << "particle " << i;
      EXPECT_EQ(batched_walk<2>(grid, i, records), expected) << "particle " << i;
      EXPECT_EQ(batched_walk<4>(grid, i, records), expected) << "particle " << i;
      EXPECT_EQ(batched_walk<7>(grid, i, records), expected) << "particle " << i;
      // The large systems' walk, with its loading hints (they change nothing read).
      EXPECT_EQ((batched_walk<2, true>(grid, i, records, counters)), expected)
          << "particle " << i;
    }
    // Particles taken out and put back elsewhere (lists relinked mid-way, heads replaced).
    for (std::int32_t i = 0; i < c.count; i += 3) {
      grid.remove(i);
      for (int k = 0; k < 3; ++k) position[i][k] = c.length * rng.uniform();
      grid.insert(i, position[i]);
    }
  }
  EXPECT_GT(handed, 0u);
  if (c.count >= 4.0 * c.length * c.length * c.length) {  // lists of about ten or more
    EXPECT_GT(longest, static_cast<std::size_t>(PairBatch::kCapacity))
        << "the dense case must fill more than one batch";
  }
}

INSTANTIATE_TEST_SUITE_P(Lists, CandidateWalk,
                         ::testing::Values(WalkCase{"LongListsWalled", 400, 3.0, false},
                                           WalkCase{"LongListsPeriodic", 600, 4.0, true},
                                           WalkCase{"ShortListsPeriodic", 500, 8.0, true},
                                           WalkCase{"SparseWalled", 60, 8.0, false}),
                         [](const ::testing::TestParamInfo<WalkCase>& info) {
                           return std::string(info.param.name);
                         });

TEST(CandidateWalk, ListLengthSeenIsTheParticleMeanOfTheirCellsCounts) {
  Domain domain;
  domain.lower = Vec3::Zero();
  domain.upper = Vec3(6.0, 5.0, 4.0);
  domain.periodic = {true, false, false};
  for (const int count : {0, 1, 50, 700}) {
    const std::vector<double> radius(count, 0.5);
    HierarchicalGrid grid(domain, radius);
    Rng rng(23);
    std::map<std::array<double, 3>, int> per_cell;  // by the cell's lower corner
    for (std::int32_t i = 0; i < count; ++i) {
      const Vec3 r(6.0 * rng.uniform(), 5.0 * rng.uniform(), 4.0 * rng.uniform());
      grid.insert(i, r);
      const Vec3 lower = grid.cell_lower(i);
      ++per_cell[{lower.x(), lower.y(), lower.z()}];
    }
    // Each particle sees its own cell's count: the mean over particles.
    double seen = 0.0;
    for (std::int32_t i = 0; i < count; ++i) {
      const Vec3 lower = grid.cell_lower(i);
      seen += per_cell[{lower.x(), lower.y(), lower.z()}];
    }
    const double expected = count > 0 ? seen / count : 0.0;
    // Sums of small integers: exact in doubles, whatever the order.
    EXPECT_EQ(grid.list_length_seen(0), expected) << count << " particles";
  }
}

}  // namespace
}  // namespace carom
