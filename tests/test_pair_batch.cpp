// The batch pair test (events/pair_batch.cpp) against its scalar twin, pair_contact.
//
// The batch computes four contact times at a time without branches; the predictions must not
// change by a bit (determinism, exact restore), so every time is compared for exact equality
// with pair_contact on the same inputs: random states with and without gravity and periodic
// images, clocks that differ, approaching, receding, missing, grazing, touching and slightly
// overlapping pairs, and batches of every length 1..kCapacity (the caller pads to whole vectors
// with a partner at rest relative to the query, which must never touch). The batch's earliest
// candidate must be the one a loop in order picks: the first of equal times (copies of a
// candidate in another lane make ties).
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "core/rng.hpp"
#include "events/event_driven/pair_batch.hpp"

namespace carom {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <bool kGravity, bool kImage>
void check_random_batches(std::uint64_t seed) {
  Rng rng(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  Domain domain;
  domain.lower = Vec3(-1.0, -2.0, 0.5);
  domain.upper = Vec3(9.0, 8.0, 10.5);
  domain.periodic = {true, false, true};
  const Vec3 gravity(0.3, -1.1, -9.81);
  int checked = 0;
  for (int round = 0; round < 400; ++round) {
    PairQuery query{Vec3(uniform(0, 8), uniform(0, 8), uniform(1, 10)),
                    Vec3(uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)), uniform(0.0, 1.0),
                    uniform(0.2, 0.6), gravity, domain};
    PairBatch batch;
    std::vector<PairState> records(PairBatch::kCapacity);
    const PairState padding = query.never_touching();
    const int count = 1 + round % PairBatch::kCapacity;
    for (int k = 0; k < count; ++k) {
      const int kind = k % 5;
      Vec3 position = query.position + Vec3(uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-1.5, 1.5));
      Vec3 velocity(uniform(-2, 2), uniform(-2, 2), uniform(-2, 2));
      double clock = uniform(0.0, 1.0);
      const double radius = uniform(0.1, 0.6);
      if (kind == 1) {  // head-on, touching or overlapping by round-off
        const Vec3 n = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
        position = query.position + (query.radius + radius) * (1.0 - 1e-15 * (k % 3)) * n;
        velocity = query.velocity + n;
        clock = query.clock;
      } else if (kind == 2) {  // same velocity: never
        velocity = query.velocity;
        clock = query.clock;
      } else if (kind == 3 && kImage) {  // across the periodic x and z faces
        position.x() += domain.length().x() * (k % 2 ? 1.0 : -1.0);
        position.z() -= domain.length().z();
      }
      records[k] = PairState{position, clock, velocity, radius};
      // A copy of an earlier candidate (another lane): equal times, the first must be chosen.
      if (round % 3 == 0 && k % 4 == 3) records[k] = records[k - 3];
      batch.add(&records[k]);
    }
    batch.pad_to_vectors(batch.count, &padding);
    ASSERT_EQ(batch.count, (count + 3) / 4 * 4) << "padded to whole vectors of four";
    contact_times<kGravity, kImage>(query, batch);
    int first_earliest = -1;  // what a loop over the candidates in order picks
    for (int k = 0; k < batch.count; ++k)
      if (batch.time[k] < (first_earliest < 0 ? kNever : batch.time[first_earliest]))
        first_earliest = k;
    ASSERT_EQ(batch.earliest, first_earliest) << "round " << round;
    for (int k = 0; k < batch.count; ++k) {
      const PairState& b = *batch.state[k];
      const double expected = pair_contact<kGravity, kImage>(
          query.position, query.velocity, query.clock, query.radius, b.position, b.velocity,
          b.clock, b.radius, gravity, domain);
      ASSERT_TRUE(same_bits(batch.time[k], expected)) << "candidate " << k << ": batch "
                                                      << batch.time[k] << " scalar " << expected;
      if (k >= count) {
        EXPECT_EQ(batch.time[k], kNever) << "padding must never touch";
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000);
}

TEST(PairBatch, StraightFlightsMatchScalarBitForBit) { check_random_batches<false, false>(1); }
TEST(PairBatch, PeriodicImagesMatchScalarBitForBit) { check_random_batches<false, true>(2); }
TEST(PairBatch, GravityMatchesScalarBitForBit) { check_random_batches<true, false>(3); }
TEST(PairBatch, GravityAndImagesMatchScalarBitForBit) { check_random_batches<true, true>(4); }

}  // namespace
}  // namespace carom
