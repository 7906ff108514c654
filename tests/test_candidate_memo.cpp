// The candidate memo of large systems (events/event_driven/candidate_memo.hpp): each particle's
// last own-level prediction leaves the first CandidateMemo::kSize candidates it walked, and
// they serve as loading hints only. That the hints change nothing is
// Determinism.LoadingHintsChangeNothing; here, what the memo holds, against a slow oracle: the
// particles whose cells lie within one cell of the particle's on every axis (periodic), found
// by comparing every pair's cell coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <set>
#include <vector>

#include "events/event_driven/engine.hpp"
#include "scenarios/scene/granular_gas.hpp"

namespace carom {
namespace {

TEST(CandidateMemo, HoldsParticlesOfTheOwnBlockAfterEachPrediction) {
  GranularGasSpec spec;
  spec.count = 2000;
  spec.volume_fraction = 0.40;
  spec.seed = 5;
  EventDrivenOptions options;
  options.prefetch_from = 0;  // memos from the first particle on
  EventDrivenEngine sim(make_granular_gas(spec), options);
  const HierarchicalGrid& grid = sim.grid();
  ASSERT_EQ(grid.levels().size(), 1u);
  const auto& level = grid.levels()[0];
  const std::size_t n = sim.particle_count();
  const Vec3 lower = sim.system().domain.lower;

  // Every particle was predicted once over its block at construction.
  std::vector<std::array<int, 3>> cell(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 corner = grid.cell_lower(static_cast<std::int32_t>(i));
    for (int k = 0; k < 3; ++k)
      cell[i][k] = static_cast<int>(std::lround((corner[k] - lower[k]) / level.cell_size[k]));
  }
  auto neighbours = [&](std::size_t i, std::size_t j) {
    for (int k = 0; k < 3; ++k) {
      const int m = level.cells[k];
      const int d = ((cell[i][k] - cell[j][k]) % m + m) % m;  // 0..m-1
      if (d != 0 && d != 1 && d != m - 1) return false;
    }
    return true;
  };
  std::size_t full = 0, short_blocks = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::set<std::int32_t> block;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i && neighbours(i, j)) block.insert(static_cast<std::int32_t>(j));
    const CandidateMemo* memo = sim.candidate_memo(i);
    ASSERT_NE(memo, nullptr);
    const std::size_t expected = std::min<std::size_t>(CandidateMemo::kSize, block.size());
    ASSERT_EQ(static_cast<std::size_t>(memo->count), expected) << "particle " << i << " with " << block.size() << " in its block";
    std::set<std::int32_t> kept;
    for (int k = 0; k < memo->count; ++k) {
      const std::int32_t c = memo->candidate(static_cast<std::int32_t>(i), k);
      EXPECT_TRUE(block.count(c)) << "particle " << i << " remembers " << c << ", not in its block";
      kept.insert(c);
    }
    EXPECT_EQ(kept.size(), expected) << "particle " << i << ": the same candidate twice";
    (block.size() >= CandidateMemo::kSize ? full : short_blocks) += 1;
  }
  // At phi = 0.40 a block holds about 20 candidates, fewer than kSize: the memo holds them all
  // (a full memo's cut is RemembersTheFirstCandidatesAsOffsets, below).
  EXPECT_GT(short_blocks, n / 2);

  // After a run (collisions, crossings, stale events) the memos still name particles only.
  sim.run_until(2.0);
  EXPECT_GT(sim.statistics().pair_events, 5000u);
  for (std::size_t i = 0; i < n; ++i) {
    const CandidateMemo& memo = *sim.candidate_memo(i);
    ASSERT_TRUE(memo.count > 0 && memo.count <= CandidateMemo::kSize) << "particle " << i;
    for (int k = 0; k < memo.count; ++k) {
      const std::int32_t c = memo.candidate(static_cast<std::int32_t>(i), k);
      ASSERT_TRUE(c >= 0 && static_cast<std::size_t>(c) < n) << "particle " << i;
    }
  }
}

// The memo's line, against the batch it was written from: the first kSize candidates in the
// walk's order, each as its offset from the particle; one whose offset does not fit 16 bits is
// kept as the particle itself (a hint of a line already loaded), at both ends of the range.
TEST(CandidateMemo, RemembersTheFirstCandidatesAsOffsets) {
  std::vector<PairState> records(70000);
  PairBatch batch;
  auto fill = [&](const std::vector<std::int32_t>& ids) {
    for (std::size_t k = 0; k < ids.size(); ++k) batch.state[k] = records.data() + ids[k];
    return static_cast<int>(ids.size());
  };
  CandidateMemo memo;
  const std::int32_t self = 40000;
  int found = fill({40005, 7232, 7231, 72767, 72768, 39999});
  memo.remember(self, batch, found, records.data());
  ASSERT_EQ(memo.count, 6);
  EXPECT_EQ(memo.candidate(self, 0), 40005);
  EXPECT_EQ(memo.candidate(self, 1), 7232);   // offset -32768: fits
  EXPECT_EQ(memo.candidate(self, 2), self);   // -32769: does not
  EXPECT_EQ(memo.candidate(self, 3), 72767);  // +32767: fits
  EXPECT_EQ(memo.candidate(self, 4), self);   // +32768: does not
  EXPECT_EQ(memo.candidate(self, 5), 39999);

  std::vector<std::int32_t> many;
  for (int k = 0; k < CandidateMemo::kSize + 9; ++k) many.push_back(self - 20 + 3 * k);
  found = fill(many);
  memo.remember(self, batch, found, records.data());
  ASSERT_EQ(memo.count, CandidateMemo::kSize);
  for (int k = 0; k < CandidateMemo::kSize; ++k) EXPECT_EQ(memo.candidate(self, k), many[k]) << k;

  found = fill({3});  // a short memo after a full one
  memo.remember(0, batch, found, records.data());
  ASSERT_EQ(memo.count, 1);
  EXPECT_EQ(memo.candidate(0, 0), 3);
}

// The memos are hints: a monodisperse gas with them from the first particle on runs bit for bit
// as without (the default prefetch_from is far above its size), through collisions, crossings
// and stale events. (Determinism.LoadingHintsChangeNothing runs a bidisperse gas, whose grid
// may have two levels, where no memos are kept.)
TEST(CandidateMemo, ChangeNothing) {
  auto run = [](std::size_t prefetch_from) {
    GranularGasSpec spec;
    spec.count = 2000;
    spec.volume_fraction = 0.40;
    spec.seed = 11;
    EventDrivenOptions options;
    options.prefetch_from = prefetch_from;
    EventDrivenEngine sim(make_granular_gas(spec), options);
    EXPECT_EQ(sim.candidate_memo(0) != nullptr, prefetch_from == 0);
    sim.run_until(2.0);
    return sim.state();
  };
  const EngineState hinted = run(0), plain = run(EventDrivenOptions{}.prefetch_from);
  EXPECT_GT(hinted.statistics.pair_events, 5000u);
  EXPECT_GT(hinted.statistics.invalid_events, 500u);
  EXPECT_GT(hinted.statistics.cell_crossings, 1000u);
  const ParticleStore &p = hinted.particles, &q = plain.particles;
  ASSERT_EQ(p.size(), q.size());
  EXPECT_EQ(std::memcmp(p.position.data(), q.position.data(), p.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(p.velocity.data(), q.velocity.data(), p.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(p.clock.data(), q.clock.data(), p.size() * sizeof(double)), 0);
  EXPECT_EQ(hinted.event_counters, plain.event_counters);
  EXPECT_EQ(hinted.statistics.events, plain.statistics.events);
  EXPECT_EQ(hinted.statistics.invalid_events, plain.statistics.invalid_events);
  EXPECT_EQ(std::memcmp(hinted.statistics.virial.data(), plain.statistics.virial.data(), 9 * sizeof(double)), 0);
}

TEST(CandidateMemo, NoneBelowPrefetchFromOrWithSeveralLevels) {
  GranularGasSpec spec;
  spec.count = 500;
  spec.volume_fraction = 0.30;
  EventDrivenEngine small(make_granular_gas(spec));  // far below the default prefetch_from
  EXPECT_EQ(small.candidate_memo(0), nullptr);

  spec.fines_diameter_ratio = 0.4;
  spec.fines_number_fraction = 0.5;
  EventDrivenOptions options;
  options.prefetch_from = 0;
  options.grid_level_ratio = 0.5;  // a level of its own for the fines
  EventDrivenEngine two_levels(make_granular_gas(spec), options);
  ASSERT_EQ(two_levels.grid().levels().size(), 2u);
  EXPECT_EQ(two_levels.candidate_memo(0), nullptr);
}

}  // namespace
}  // namespace carom
