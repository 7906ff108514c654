// The Monte Carlo method's random parts against exact statistics: the collision grid's cell
// statistics against a two-pass oracle, partner velocities drawn from them, the impact point
// over the collision cross-section, the contact value.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/rng.hpp"
#include "events/monte_carlo/collision_grid.hpp"
#include "events/monte_carlo/partner_sampling.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

// 300 particles of species 0 in one cell with an anisotropic, shifted velocity distribution,
// 50 of species 1 elsewhere. The cell's statistics, with one particle left out, against the
// two-pass mean and population standard deviation of the other 299: exact to round-off (1e-12
// relative; the one-pass sums lose ~1e-15 relative here, far below).
TEST(MonteCarloGrid, CellStatisticsMatchTwoPassOracle) {
  Domain domain;
  domain.upper = Vec3(10, 10, 10);
  CollisionGrid grid(domain, 5.0, 2);
  ASSERT_EQ(grid.cell_count(), 8u);
  Rng rng(7);
  std::vector<Vec3> v, w;
  const Vec3 mean(1.0, -2.0, 0.5), spread(0.3, 1.5, 0.7);
  for (int i = 0; i < 300; ++i) {
    v.push_back(mean + spread.cwiseProduct(rng.normal3()));
    w.push_back(rng.normal3());
    grid.add(Vec3(rng.uniform(0, 5), rng.uniform(0, 5), rng.uniform(0, 5)), 0, 0.5, v.back(), w.back());
  }
  for (int i = 0; i < 50; ++i) grid.add(Vec3(7, 7, 7), 1, 0.25, Vec3::Zero(), Vec3::Zero());
  const std::int32_t cell = grid.cell_of(Vec3(1, 1, 1));
  const OwnContribution own{0, 0.5, v[0], w[0]};
  const PartnerStatistics p = grid.partners(cell, 0, &own);
  Vec3 m = Vec3::Zero(), ms = Vec3::Zero(), var = Vec3::Zero();
  for (int i = 1; i < 300; ++i) {
    m += v[i] / 299.0;
    ms += w[i] / 299.0;
  }
  for (int i = 1; i < 300; ++i) var += (v[i] - m).cwiseProduct(v[i] - m) / 299.0;
  EXPECT_EQ(p.count, 299.0);
  EXPECT_NEAR(p.number_density, 299.0 / 125.0, 1e-12);
  EXPECT_NEAR(p.mean_radius, 0.5, 1e-12);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p.mean_velocity[k], m[k], 1e-12 * (1 + std::abs(m[k])));
    EXPECT_NEAR(p.velocity_std[k], std::sqrt(var[k]), 1e-12 * (1 + std::sqrt(var[k])));
    EXPECT_NEAR(p.mean_spin[k], ms[k], 1e-12);
  }
  // Species 1 is not in this cell; a particle of species 1 does not remove itself from species 0.
  EXPECT_EQ(grid.partners(cell, 1, nullptr).count, 0.0);
  EXPECT_EQ(grid.partners(grid.cell_of(Vec3(7, 7, 7)), 1, &own).count, 50.0);
  // Solid fraction of the first cell: 300 spheres of radius 0.5 in 125 m^3.
  EXPECT_NEAR(grid.solid_fraction(cell), 300 * std::numbers::pi / 6.0 / 125.0, 1e-12);
}

// The cell lists of partner drawing (monte_carlo.partner = "cell_particle") against a brute
// force over 2000 particles of 3 species in 27 cells of a periodic box (positions outside the
// box wrapped): each cell's list of each species holds exactly the particles there, in index
// order, and the largest deviation from the cell's mean velocity is the brute-force maximum
// (exact: the same arithmetic; 1e-12 relative allows for the sums' order).
TEST(MonteCarloGrid, CellListsMatchBruteForce) {
  Domain domain;
  domain.upper = Vec3(9, 9, 9);
  domain.periodic = {true, true, true};
  CollisionGrid grid(domain, 3.0, 3);
  ASSERT_EQ(grid.cell_count(), 27u);
  Rng rng(11);
  std::vector<Vec3> r, v;
  std::vector<std::uint32_t> species;
  std::vector<std::int32_t> cell;
  for (int i = 0; i < 2000; ++i) {
    r.push_back(Vec3(rng.uniform(-2, 11), rng.uniform(0, 9), rng.uniform(0, 9)));
    v.push_back(Vec3(0.5, 0, 0) + rng.normal3());
    species.push_back(static_cast<std::uint32_t>(i % 3));
    cell.push_back(grid.add(r.back(), species.back(), 0.1, v.back(), Vec3::Zero()));
  }
  grid.list_members(cell, species, v);
  std::size_t listed = 0;
  for (std::int32_t c = 0; c < 27; ++c)
    for (std::uint32_t s = 0; s < 3; ++s) {
      std::vector<std::uint32_t> expected;
      Vec3 mean = Vec3::Zero();
      for (std::size_t i = 0; i < r.size(); ++i)
        if (species[i] == s && grid.cell_of(r[i]) == c) {
          expected.push_back(static_cast<std::uint32_t>(i));
          mean += v[i];
        }
      const auto list = grid.members(c, s);
      ASSERT_EQ(std::vector<std::uint32_t>(list.begin(), list.end()), expected)
          << "cell " << c << " species " << s;
      listed += list.size();
      if (expected.empty()) continue;
      mean /= double(expected.size());
      EXPECT_NEAR((grid.mean_velocity(c, s) - mean).norm(), 0.0, 1e-12);
      double largest = 0.0;
      for (std::uint32_t i : expected) largest = std::max(largest, (v[i] - mean).norm());
      EXPECT_NEAR(grid.largest_deviation(c, s), largest, 1e-12 * largest);
    }
  EXPECT_EQ(listed, r.size());
}

// Partner velocities drawn from given statistics: the sample mean and standard deviation of
// 200000 draws per component against the statistics. With N draws the sample mean has standard
// error sigma/sqrt(N) and the sample standard deviation sigma/sqrt(2N) (Gaussian); 4.5 standard
// errors give a two-sided confidence of 99.9993 % per check (12 checks: a false failure in
// 1e-4 of seeds). A wrong component order or a variance used as a deviation fails by far more.
TEST(MonteCarloSampling, PartnersReproduceMeanAndStandardDeviation) {
  PartnerStatistics p;
  p.count = 20;
  p.mean_velocity = Vec3(0.4, -1.2, 3.0);
  p.velocity_std = Vec3(0.2, 1.0, 2.5);
  Rng rng(11);
  const int n = 200000;
  Vec3 sum = Vec3::Zero(), square = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    const Vec3 v = sample_partner_velocity(p, rng);
    sum += v;
    square += v.cwiseProduct(v);
  }
  const Vec3 mean = sum / n;
  for (int k = 0; k < 3; ++k) {
    const double sd = std::sqrt(square[k] / n - mean[k] * mean[k]);
    const double sigma = p.velocity_std[k];
    EXPECT_NEAR(mean[k], p.mean_velocity[k], 4.5 * sigma / std::sqrt(n)) << "component " << k;
    EXPECT_NEAR(sd, sigma, 4.5 * sigma / std::sqrt(2.0 * n)) << "component " << k;
  }
}

// The impact point is uniform over the disc of radius R1 + R0 perpendicular to g: then
// u = sin^2 of the angle between -g and n is uniform on [0, 1) (mean 1/2, variance 1/12),
// every impact approaches (g . n < 0), n is a unit vector, and the azimuth is uniform (the
// mean of the disc component vanishes). 100000 draws: standard error of the mean of u is
// sqrt(1/12/N) = 9.1e-4; tolerance 4.5 of them.
TEST(MonteCarloSampling, ImpactPointUniformOverCrossSection) {
  Rng rng(3);
  const Vec3 g(0.3, -2.0, 0.7);
  const Vec3 along = g.normalized();
  const int n = 100000;
  double u_sum = 0.0, u_square = 0.0;
  Vec3 side = Vec3::Zero();
  for (int i = 0; i < n; ++i) {
    const Vec3 normal = sample_impact_normal(g, rng);
    ASSERT_NEAR(normal.norm(), 1.0, 1e-14);
    ASSERT_LT(g.dot(normal), 0.0);
    const double c = -along.dot(normal);
    const double u = 1.0 - c * c;
    u_sum += u;
    u_square += u * u;
    side += normal + c * along;
  }
  const double se = std::sqrt(1.0 / 12.0 / n);
  EXPECT_NEAR(u_sum / n, 0.5, 4.5 * se);
  EXPECT_NEAR(u_square / n - std::pow(u_sum / n, 2), 1.0 / 12.0, 0.003);
  EXPECT_LT((side / n).norm(), 4.5 * std::sqrt(0.5 * 0.5 / n) * 1.5);
}

// For one size the mixture contact value is Carnahan-Starling's, and tests/VALIDATION.md's table.
TEST(MonteCarloSampling, ContactValueIsCarnahanStarlingForOneSize) {
  for (double phi : {0.1, 0.2, 0.3, 0.4}) {
    const double d = 1.0, xi2 = phi / d;  // xi2 = (pi/6) n d^2 = phi / d for one size
    EXPECT_NEAR(contact_value(ContactValue::Enskog, phi, xi2, d, d), test::carnahan_starling_g0(phi), 1e-12);
  }
  EXPECT_NEAR(contact_value(ContactValue::Enskog, 0.1, 0.1, 1, 1), 1.30316, 1e-5);
  EXPECT_EQ(contact_value(ContactValue::None, 0.3, 0.3, 1, 1), 1.0);
}

}  // namespace
}  // namespace carom
