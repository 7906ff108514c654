// Placing entering particles (events/flow/inflow_placement.hpp, the inflow side of
// FlowBoundaries): the bucket grid's free-place test against brute force, no overlap after
// insertion into slabs already holding particles (periodic images, a cylinder wall), the
// statistics of positions and velocities, the default depth and the checks of a definition.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "events/flow/inflow_placement.hpp"
#include "flow_test_support.hpp"

using namespace carom;
using namespace carom::flow_test;

namespace {

/// The obviously correct test: gap >= 0 to every sphere (periodic distance: the minimum image),
/// every wall and the box faces on walled axes.
bool free_brute_force(const Vec3& r, double a, const ParticleStore& p, const System& system) {
  const Domain& d = system.domain;
  for (int k = 0; k < 3; ++k)
    if (!d.periodic[k] && (r[k] - a < d.lower[k] || r[k] + a > d.upper[k])) return false;
  for (const Wall& w : system.walls)
    if (!(w.gap(r, a) >= 0.0)) return false;
  for (std::size_t j = 0; j < p.size(); ++j) {
    Vec3 separation = r - p.position[j];
    d.minimum_image(separation);
    if (!(separation.norm() - (a + p.radius[j]) >= 0.0)) return false;
  }
  return true;
}

/// Spheres of radius 1.5 mm or 0.5 mm placed at random (brute force, no overlap) in `region`.
ParticleStore random_spheres(const System& system, const Box& region, int tries, Rng& rng) {
  ParticleStore p;
  for (int t = 0; t < tries; ++t) {
    const std::uint32_t s = rng.uniform() < 0.5 ? 0 : 1;
    const Species& kind = system.species[s];
    Vec3 r;
    for (int k = 0; k < 3; ++k) r[k] = rng.uniform(region.lower[k], region.upper[k]);
    if (free_brute_force(r, kind.radius(), p, system))
      p.add(r, Vec3::Zero(), Vec3::Zero(), kind.radius(), kind.mass(), kind.inertia(), s, p.size());
  }
  return p;
}

/// Box periodic on x and y (1.5 cm), walled on z (5 cm), species 3 mm and 1 mm.
System periodic_column() {
  System system;
  system.domain.upper = Vec3(0.015, 0.015, 0.05);
  system.domain.periodic = {true, true, false};
  system.walls = box_walls(system.domain);
  system.species = {Species{"big", 3e-3, 2500.0}, Species{"fine", 1e-3, 2500.0}};
  return system;
}

/// Every pair with a new particle (index >= first_new) apart, every new one clear of the walls
/// and the box: brute force over all pairs. Returns the number of pairs checked.
std::size_t expect_no_overlap(const ParticleStore& p, std::size_t first_new, const System& system) {
  std::size_t pairs = 0;
  for (std::size_t i = first_new; i < p.size(); ++i) {
    for (const Wall& w : system.walls) EXPECT_GE(w.gap(p.position[i], p.radius[i]), 0.0) << w.name;
    for (int k = 0; k < 3; ++k)
      if (!system.domain.periodic[k]) {
        EXPECT_GE(p.position[i][k] - p.radius[i], system.domain.lower[k]);
        EXPECT_LE(p.position[i][k] + p.radius[i], system.domain.upper[k]);
      }
    for (std::size_t j = 0; j < i; ++j, ++pairs) {
      Vec3 separation = p.position[i] - p.position[j];
      system.domain.minimum_image(separation);
      EXPECT_GE(separation.norm() - (p.radius[i] + p.radius[j]), 0.0) << i << " " << j;
    }
  }
  return pairs;
}

}  // namespace

// The fast path against its oracle: for 20 000 random centres the bucket grid's answer equals
// the brute-force one, on a box periodic on two axes (images across both faces) with spheres of
// two sizes, some touching the slab from outside it. Exact agreement: both compute the same
// gaps; the grid must only not miss a sphere.
TEST(InflowPlacement, FreePlaceTestAgreesWithBruteForce) {
  const System system = periodic_column();
  Rng rng(17);
  const ParticleStore spheres =
      random_spheres(system, Box{Vec3(0, 0, 0.02), Vec3(0.015, 0.015, 0.05)}, 4000, rng);
  const Box centres{Vec3(0.0005, 0.0005, 0.03), Vec3(0.0145, 0.0145, 0.04)};
  SlabPlacer placer(centres, 0.5e-3, 1.5e-3, system.domain, system.walls);
  for (std::size_t j = 0; j < spheres.size(); ++j)
    placer.add(spheres.position[j], spheres.radius[j]);
  int free_count = 0;
  for (int t = 0; t < 20000; ++t) {
    Vec3 r;
    for (int k = 0; k < 3; ++k) r[k] = rng.uniform(centres.lower[k], centres.upper[k]);
    const bool expected = free_brute_force(r, 0.5e-3, spheres, system);
    ASSERT_EQ(placer.free(r), expected) << r.transpose();
    free_count += expected;
  }
  EXPECT_GT(free_count, 1000) << "both answers should occur";
  EXPECT_LT(free_count, 19000);
}

// Two inflows (big and fine beads) whose slabs overlap, filling a periodic column that already
// holds beads in and around the slabs until they block: no new bead overlaps any bead, old or
// new (brute force over all pairs with the minimum image), nor the walls.
TEST(InflowPlacement, NoOverlapInASlabAlreadyHoldingParticlesPeriodic) {
  System system = periodic_column();
  Rng rng(23);
  ParticleStore particles =
      random_spheres(system, Box{Vec3(0, 0, 0.03), Vec3(0.015, 0.015, 0.05)}, 250, rng);
  ASSERT_GT(particles.size(), 100u);
  Inflow big;
  big.name = "big";
  big.species = 0;
  big.axis = 2;
  big.plane = 0.048;
  big.direction = -1;
  big.lower = Vec3(0.0, 0.0, 0.0);
  big.upper = Vec3(0.015, 0.015, 0.0);
  big.mass_flow = 1e5 * system.species[0].mass();
  big.depth = 0.012;
  Inflow fine = big;
  fine.name = "fine";
  fine.species = 1;
  fine.plane = 0.045;
  fine.mass_flow = 1e6 * system.species[1].mass();
  system.particles = particles;
  FlowBoundaries flow({big, fine}, {}, system, 4, 0.0, kStep);
  ParticleChange change;
  flow.step(kStep, particles, change);
  const std::size_t before = particles.size();
  apply(change, particles);
  EXPECT_GT(flow.inflow_counters(0).entered, 5u);
  EXPECT_GT(flow.inflow_counters(1).entered, 100u);
  EXPECT_GT(flow.inflow_counters(1).waiting(), 0u) << "the slab should be filled to blocking";
  EXPECT_GT(expect_no_overlap(particles, before, system), 10000u);
}

// A cylinder wall cuts the inlet rectangle (its corners lie outside the cylinder): new beads
// keep a gap >= 0 to the cylinder and to the beads already there.
TEST(InflowPlacement, NoOverlapWithACylinderWall) {
  System system;
  system.domain.lower = Vec3(-0.01, -0.01, 0.0);
  system.domain.upper = Vec3(0.01, 0.01, 0.05);
  system.walls = box_walls(system.domain);
  system.walls.push_back(Wall::cylinder("tube", 0.0, 0.0, 0.008));
  system.species = {Species{"big", 3e-3, 2500.0}, Species{"fine", 1e-3, 2500.0}};
  Rng rng(29);
  ParticleStore particles =
      random_spheres(system, Box{Vec3(-0.01, -0.01, 0.03), Vec3(0.01, 0.01, 0.05)}, 300, rng);
  Inflow fine;
  fine.name = "fine";
  fine.species = 1;
  fine.axis = 2;
  fine.plane = 0.045;
  fine.direction = -1;
  fine.lower = Vec3(-0.01, -0.01, 0.0);
  fine.upper = Vec3(0.01, 0.01, 0.0);
  fine.mass_flow = 1e6 * system.species[1].mass();
  fine.depth = 0.01;
  system.particles = particles;
  FlowBoundaries flow({fine}, {}, system, 6, 0.0, kStep);
  ParticleChange change;
  flow.step(kStep, particles, change);
  const std::size_t before = particles.size();
  apply(change, particles);
  EXPECT_GT(flow.inflow_counters(0).entered, 100u);
  expect_no_overlap(particles, before, system);
}

// Placement statistics from ~10 000 beads entering an empty slab one at a time (each step's
// store is empty, so nothing but the slab shapes the positions): the centres are uniform over
// the slab shrunk by the radius (chi-square over 10 x 10 bins across the rectangle, and over 5
// bins through the depth, each below its 99.9 % quantile), and each velocity component's mean
// and standard deviation are within 4 standard errors of the set ones (two-sided 4 sigma: a
// false failure has probability 6e-5 per check).
TEST(InflowPlacement, PositionsUniformAndVelocitiesAsSet) {
  System system = duct();
  Inflow in = top_inflow(system, 500.0);
  in.velocity = Vec3(0.5, -0.3, -1.0);
  in.velocity_spread = Vec3(0.1, 0.2, 0.3);
  FlowBoundaries flow({in}, {}, system, 31, 0.0, kStep);
  const double a = system.species[0].radius();
  const Box centres = inflow_centres(in, flow.inflows()[0].depth, a);
  std::vector<Vec3> r, v;
  for (int k = 1; k <= 20000; ++k) {
    ParticleChange change;
    flow.step(k * kStep, ParticleStore{}, change);
    ASSERT_LE(change.added.size(), 1u);
    for (std::size_t j = 0; j < change.added.size(); ++j) {
      r.push_back(change.added.position[j]);
      v.push_back(change.added.velocity[j]);
    }
  }
  const double n = static_cast<double>(r.size());
  ASSERT_GT(n, 9900.0);
  std::vector<double> across(100, 0.0), through(5, 0.0);
  for (const Vec3& x : r) {
    ASSERT_TRUE(centres.contains(x)) << x.transpose();
    const Vec3 u = (x - centres.lower).cwiseQuotient(centres.upper - centres.lower);
    across[std::min(9, int(u.x() * 10)) + 10 * std::min(9, int(u.y() * 10))] += 1.0;
    through[std::min(4, int(u.z() * 5))] += 1.0;
  }
  const auto chi_square = [&](const std::vector<double>& counts) {
    const double expected = n / counts.size();
    double sum = 0.0;
    for (double c : counts) sum += (c - expected) * (c - expected) / expected;
    return sum;
  };
  // 99.9 % quantile of chi-square with k degrees of freedom (Wilson-Hilferty, z = 3.090).
  const auto quantile = [](double k) {
    const double h = 2.0 / (9.0 * k);
    return k * std::pow(1.0 - h + 3.090 * std::sqrt(h), 3.0);
  };
  EXPECT_LT(chi_square(across), quantile(99.0));
  EXPECT_LT(chi_square(through), quantile(4.0));
  for (int k = 0; k < 3; ++k) {
    double mean = 0.0, square = 0.0;
    for (const Vec3& u : v) mean += u[k] / n;
    for (const Vec3& u : v) square += (u[k] - mean) * (u[k] - mean) / (n - 1.0);
    const double sd = std::sqrt(square), sigma = in.velocity_spread[k];
    EXPECT_NEAR(mean, in.velocity[k], 4.0 * sigma / std::sqrt(n)) << k;
    EXPECT_NEAR(sd, sigma, 4.0 * sigma / std::sqrt(2.0 * (n - 1.0))) << k;
  }
}

// The default depth: two diameters, or what the mean speed along the axis crosses in one
// interval plus a diameter, whichever is more.
TEST(InflowPlacement, DefaultDepth) {
  const System system = duct();
  Inflow in = top_inflow(system, 100.0);
  EXPECT_DOUBLE_EQ(inflow_depth(in, system.species[0], 1e-3), 4e-3);  // 1 mm + d < 2 d
  in.velocity.z() = -5.0;
  EXPECT_DOUBLE_EQ(inflow_depth(in, system.species[0], 1e-3), 7e-3);  // 5 mm + d
  in.depth = 0.01;
  EXPECT_DOUBLE_EQ(inflow_depth(in, system.species[0], 1e-3), 0.01);
}

// Definitions that cannot run are refused with a message naming the inflow or outflow and the
// key at fault.
TEST(InflowPlacement, BadDefinitionsAreRefused) {
  System system = duct();
  system.domain.periodic[0] = true;
  system.walls = box_walls(system.domain);
  system.species.push_back(Species{"post", 2e-3, 2500.0, true});
  const Inflow good = top_inflow(system, 100.0);
  struct Case {
    std::string what;
    std::function<void(Inflow&, Outflow&)> change;
    std::string expected;
  };
  const std::vector<Case> cases{
      {"plane outside", [](Inflow& i, Outflow&) { i.plane = 0.1; },
       "\"top\": plane is not strictly inside"},
      {"periodic axis", [](Inflow& i, Outflow&) { i.axis = 0; },
       "\"top\": axis is a periodic axis"},
      {"empty rectangle", [](Inflow& i, Outflow&) { i.upper.y() = 0.0; },
       "\"top\": max must exceed min"},
      {"rectangle outside", [](Inflow& i, Outflow&) { i.upper.y() = 0.03; },
       "is not inside the domain"},
      {"no mass flow", [](Inflow& i, Outflow&) { i.mass_flow = 0.0; },
       "\"top\": mass_flow must be a positive"},
      {"slab outside", [](Inflow& i, Outflow&) { i.depth = 0.095; }, "reaches outside the domain"},
      {"slab too thin", [](Inflow& i, Outflow&) { i.depth = 1.5e-3; },
       "depth makes the slab too thin"},
      {"rectangle too narrow", [](Inflow& i, Outflow&) { i.lower.y() = 0.0195; },
       "max makes the slab too thin"},
      {"beyond outlet",
       [](Inflow&, Outflow& o) {
         o.plane = 0.088;
         o.direction = 1;
       },
       "beyond outflow \"out\""},
      {"outlet outside", [](Inflow&, Outflow& o) { o.plane = -0.01; },
       "outflow \"out\": plane is not strictly"},
      {"outlet on a periodic axis",
       [](Inflow&, Outflow& o) {
         o.axis = 0;
         o.plane = 0.01;
       },
       "outflow \"out\": axis is a periodic axis"},
      {"fixed species", [](Inflow& i, Outflow&) { i.species = 1; },
       "\"top\": species is a fixed species"},
      {"no attempts", [](Inflow& i, Outflow&) { i.attempts = 0; }, "attempts must be at least 1"},
  };
  for (const Case& c : cases) {
    Inflow in = good;
    Outflow out{"out", 2, 0.01, -1};
    c.change(in, out);
    try {
      FlowBoundaries flow({in}, {out}, system, 1, 0.0, kStep);
      ADD_FAILURE() << c.what << ": accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << c.what << ": " << e.what();
    }
  }
}
