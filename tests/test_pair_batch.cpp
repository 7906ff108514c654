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

#include <cmath>
#include <cstring>
#include <vector>

#include "core/rng.hpp"
#include "events/event_driven/pair_batch.hpp"

namespace carom {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// A box periodic in x and z, walled in y.
Domain test_box() {
  Domain domain;
  domain.lower = Vec3(-1.0, -2.0, 0.5);
  domain.upper = Vec3(9.0, 8.0, 10.5);
  domain.periodic = {true, false, true};
  return domain;
}

template <bool kGravity, bool kImage>
void check_random_batches(std::uint64_t seed) {
  Rng rng(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  const Domain domain = test_box();
  const Vec3 gravity(0.3, -1.1, -9.81);
  int checked = 0;
  for (int round = 0; round < 400; ++round) {
    PairQuery query{Vec3(uniform(0, 8), uniform(0, 8), uniform(1, 10)),
                    Vec3(uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)),
                    uniform(0.0, 1.0),
                    uniform(0.2, 0.6),
                    gravity,
                    domain};
    PairBatch batch;
    std::vector<PairState> records(PairBatch::kCapacity);
    const PairState padding = query.never_touching();
    const int count = 1 + round % PairBatch::kCapacity;
    for (int k = 0; k < count; ++k) {
      const int kind = k % 5;
      Vec3 position =
          query.position + Vec3(uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-1.5, 1.5));
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
      ASSERT_TRUE(same_bits(batch.time[k], expected))
          << "candidate " << k << ": batch " << batch.time[k] << " scalar " << expected;
      if (k >= count) {
        EXPECT_EQ(batch.time[k], kNever) << "padding must never touch";
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000);
}

// The relax predictions' batch reach test (reach_tests) against its scalar twin may_reach: the
// same decision for every candidate, on random records around the query (inside, near and far
// beyond reach; across periodic faces with kImage; clocks before and after the query's end) and
// the decisive cases made on purpose: a candidate at exactly the reach along one axis, and one
// at the reach along a diagonal. Each decision is also checked against its definition with
// exact (long double) arithmetic away from the margin: a candidate farther than the radii plus
// both reach bounds by more than 1e-9 must be refused, one nearer by 1e-9 accepted.
template <bool kImage>
void check_random_reach_batches(std::uint64_t seed) {
  Rng rng(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  const Domain domain = test_box();
  int checked = 0, refused = 0, accepted = 0;
  for (int round = 0; round < 400; ++round) {
    RelaxFlightBounds bounds{uniform(0.0, 40.0), uniform(0.0, 100.0)};
    const double end = uniform(0.0, 0.05);
    const ReachQuery query{Vec3(uniform(0, 8), uniform(0, 8), uniform(1, 10)),
                           uniform(0.2, 0.6),
                           uniform(0.0, 0.3),
                           end,
                           bounds,
                           domain};
    PairBatch batch;
    std::vector<PairState> records(PairBatch::kCapacity);
    const int count = 1 + round % PairBatch::kCapacity;
    for (int k = 0; k < count; ++k) {
      const Vec3 velocity(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3));
      const double clock = end - uniform(-0.01, 0.05);
      const double radius = uniform(0.1, 0.6);
      const double reach =
          query.radius + radius + query.sweep + bounds.reach_bound(velocity, end - clock);
      Vec3 offset(uniform(-1.8, 1.8), uniform(-1.8, 1.8), uniform(-1.8, 1.8));
      if (k % 6 == 1) offset = Vec3(reach, 0.0, 0.0);                      // at the reach
      if (k % 6 == 2) offset = Vec3(1.0, -1.0, 1.0).normalized() * reach;  // diagonally
      Vec3 position = query.position + offset;
      if (kImage && k % 6 == 3) {  // across the periodic x and z faces
        position.x() += domain.length().x() * (k % 2 ? 1.0 : -1.0);
        position.z() -= domain.length().z();
      }
      records[k] = PairState{position, clock, velocity, radius};
      batch.add(&records[k]);
    }
    batch.pad_to_vectors(batch.count, &records[0]);
    const std::uint64_t reached = reach_tests<kImage>(query, batch);
    for (int k = 0; k < count; ++k) {
      const PairState& b = *batch.state[k];
      const bool scalar = may_reach<kImage>(query, b);
      ASSERT_EQ(((reached >> k) & 1) == 1, scalar) << "candidate " << k << ", round " << round;
      // The definition, in long double.
      Vec3 gap = query.position - b.position;
      if (kImage) domain.minimum_image(gap);
      const long double distance = std::sqrt((long double)gap.squaredNorm());
      const long double span = (long double)end - b.clock;
      const long double speed = std::abs((long double)b.velocity.x()) +
                                std::abs((long double)b.velocity.y()) +
                                std::abs((long double)b.velocity.z());
      const long double reach = query.radius + (long double)b.radius + query.sweep +
                                span * (speed + 0.5L * span * (bounds.drive + bounds.rate * speed));
      if (distance > reach + 1e-9L) {
        EXPECT_FALSE(scalar) << "candidate " << k << " beyond reach was accepted";
        ++refused;
      } else if (distance < reach - 1e-9L) {
        EXPECT_TRUE(scalar) << "candidate " << k << " within reach was refused";
        ++accepted;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000);
  EXPECT_GT(refused, 1000) << "too few candidates beyond reach to test the refusals";
  EXPECT_GT(accepted, 1000) << "too few candidates within reach to test the acceptances";
}

TEST(PairBatch, ReachTestsMatchScalarBitForBit) {
  check_random_reach_batches<false>(5);
}
TEST(PairBatch, ReachTestsWithImagesMatchScalarBitForBit) {
  check_random_reach_batches<true>(6);
}

TEST(PairBatch, StraightFlightsMatchScalarBitForBit) {
  check_random_batches<false, false>(1);
}
TEST(PairBatch, PeriodicImagesMatchScalarBitForBit) {
  check_random_batches<false, true>(2);
}
TEST(PairBatch, GravityMatchesScalarBitForBit) {
  check_random_batches<true, false>(3);
}
TEST(PairBatch, GravityAndImagesMatchScalarBitForBit) {
  check_random_batches<true, true>(4);
}

}  // namespace
}  // namespace carom
