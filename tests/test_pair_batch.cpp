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

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/relax_roots.hpp"
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
  int checked = 0, refused = 0, accepted = 0, lines_ended = 0;
  for (int round = 0; round < 400; ++round) {
    RelaxFlightBounds bounds{uniform(0.0, 40.0), uniform(0.0, 100.0)};
    const double end = uniform(0.0, 0.05);
    ReachQuery query{Vec3(uniform(0, 8), uniform(0, 8), uniform(1, 10)),
                     uniform(0.2, 0.6),
                     uniform(0.0, 0.3),
                     end,
                     bounds,
                     domain};
    // The line test's part of the query.
    query.velocity = Vec3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3));
    query.clock = end - uniform(0.0, 0.05);
    query.acceleration = uniform(0.0, 50.0);
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
    const std::uint64_t reached_lines = reach_tests<kImage, true>(query, batch);
    for (int k = 0; k < count; ++k) {
      const PairState& b = *batch.state[k];
      const bool scalar = may_reach<kImage>(query, b);
      ASSERT_EQ(((reached >> k) & 1) == 1, scalar) << "candidate " << k << ", round " << round;
      const bool apart = lines_apart<kImage>(query, b);
      ASSERT_EQ(((reached_lines >> k) & 1) == 1, scalar && !apart)
          << "candidate " << k << ", round " << round << " (with the line test)";
      lines_ended += scalar && apart;
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
  EXPECT_GT(lines_ended, 1000) << "too few candidates within reach that the line test ends";
}

TEST(PairBatch, ReachTestsMatchScalarBitForBit) {
  check_random_reach_batches<false>(5);
}
TEST(PairBatch, ReachTestsWithImagesMatchScalarBitForBit) {
  check_random_reach_batches<true>(6);
}

// The line test's promise (lines_apart): every pair it ends never touches before the query's
// end, so relax_pair_time, which asks it first, returns what its exact tests and contact search
// would (kNever). The reference is that search itself (relax_pair_contact_time, to round-off
// with a touching tolerance of 1e-13 of the contact) on the states advanced to the later clock,
// as relax_pair_time does it. Random pairs under strong, unequal drag and drive (the strays
// |a| s^2 / 2 reach a sphere's diameter, so the test's bounds matter), clocks that differ,
// positions from overlapping to a few diameters apart, velocities aimed at the partner or past
// it, with and without periodic images. Both outcomes must be common: pairs the line test ends,
// and pairs that touch (which it must not end); and it must end nearly every pair on one clock
// that starts a fifth of the contact apart and separates under little drive and drag (what it
// is for).
template <bool kImage>
void check_lines_apart_never_ends_a_contact(std::uint64_t seed) {
  Rng rng(seed);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
  auto random_vector = [&](double size) {
    return Vec3(uniform(-size, size), uniform(-size, size), uniform(-size, size));
  };
  const Domain domain = test_box();
  int ended = 0, touching = 0, separating = 0, separating_ended = 0;
  for (int round = 0; round < 40000; ++round) {
    const bool gentle = round % 4 == 0;  // little drive and drag: the lines nearly exact
    const double drive_size = gentle ? 0.01 : 40.0, rate_size = gentle ? 0.1 : 30.0;
    const RelaxFlight fa{uniform(0.0, rate_size), random_vector(drive_size)};
    const RelaxFlight fb{round % 3 == 0 ? fa.rate : uniform(0.0, rate_size),
                         random_vector(drive_size)};
    RelaxFlightBounds bounds;
    bounds.include(fa);
    bounds.include(fb);
    const double ra = uniform(0.2, 0.6), rb = uniform(0.2, 0.6), contact = ra + rb;
    const Vec3 pa(uniform(0, 8), uniform(-1, 7), uniform(1, 10));
    const Vec3 direction = random_vector(1.0).normalized();
    Vec3 pb = pa + direction * (contact * uniform(0.95, 2.5));
    if (kImage && round % 5 == 1) pb.x() += domain.length().x();  // an image across x
    const double speed = uniform(0.0, 5.0);
    Vec3 va = random_vector(speed), vb = random_vector(speed);
    if (round % 3 == 1) vb = va + direction * uniform(-speed, speed);  // along the line
    const double ca = uniform(0.0, 0.1), cb = gentle || round % 4 == 1 ? ca : uniform(0.0, 0.1);
    const double end = std::max(ca, cb) + uniform(0.0, 0.2);

    ReachQuery query{pa, ra, 0.0, end, bounds, domain};
    query.velocity = va;
    query.clock = ca;
    query.acceleration = fa.acceleration(va).norm();
    const PairState b{pb, cb, vb, rb};
    const bool apart = lines_apart<kImage>(query, b);

    // relax_pair_time's exact path: both states at the later clock, then the contact search.
    const double t_ref = std::max(ca, cb);
    Vec3 dr = pa - pb, wa = va, wb = vb;
    if (t_ref > ca) {
      dr += fa.displacement(va, t_ref - ca);
      wa = fa.velocity(va, t_ref - ca);
    }
    if (t_ref > cb) {
      dr -= fb.displacement(vb, t_ref - cb);
      wb = fb.velocity(vb, t_ref - cb);
    }
    if (kImage) domain.minimum_image(dr);
    const double s = relax_pair_contact_time(dr, wa, fa, wb, fb, contact, end - t_ref);
    if (apart) {
      ASSERT_EQ(s, kNever) << "round " << round << ": the line test ended a pair that touches at "
                           << s;
    }
    ended += apart;
    touching += s != kNever;
    Vec3 gap = pa - pb;
    if (kImage) domain.minimum_image(gap);
    if (gentle && gap.norm() > 1.2 * contact && gap.dot(va - vb) > 0.0) {
      ++separating;
      separating_ended += apart;
    }
  }
  std::printf("pairs ended by the line test %d, touching %d, separating %d (ended %d)\n", ended,
              touching, separating, separating_ended);
  EXPECT_GT(ended, 4000) << "too few pairs ended by the line test";
  EXPECT_GT(touching, 2000) << "too few touching pairs to check";
  EXPECT_GT(separating, 1000);
  EXPECT_GT(separating_ended, 0.9 * separating)
      << "the line test should end nearly every pair that starts apart and separates";
}

TEST(PairBatch, LinesApartNeverEndsAContact) {
  check_lines_apart_never_ends_a_contact<false>(7);
}
TEST(PairBatch, LinesApartWithImagesNeverEndsAContact) {
  check_lines_apart_never_ends_a_contact<true>(8);
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
