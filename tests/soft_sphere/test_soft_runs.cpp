// Soft-sphere runs of many particles: the Verlet lists against brute force, the elastic gas
// against Enskog, homogeneous cooling against Haff, a column at rest carrying its weight, the
// detectors on both sides of their limits, determinism and checkpoints bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>

#include <unistd.h>

#include "core/hdf5.hpp"
#include "core/rng.hpp"
#include "scenarios/scene/granular_gas.hpp"
#include "tests/soft_sphere/soft_support.hpp"
#include "tests/test_support.hpp"

namespace carom {
namespace {

using namespace soft_test;

double temperature(const CollisionMethod& sim) {
  return 2.0 * sim.energies().translational / (3.0 * (double(sim.particle_count()) - 1.0));
}

/// The linear model with every pair's contact lasting `contact_time`, step contact_time / steps.
SoftSphereOptions linear_gas_options(double contact_time, double steps) {
  SoftSphereOptions o;
  o.model = ContactModel::Linear;
  o.contact_time = contact_time;
  o.time_step = contact_time / steps;
  return o;
}

// Every pair within the skin, on a polydisperse (1:10) walled box, periodic in x and y, and
// periodic on every axis, against the all-pairs scan: the same pairs in the same order. (The
// large spheres' searches wrap around the periodic axes: two runs of cells per axis.)
TEST(SoftNeighbours, VerletListsAgreeWithBruteForce) {
  for (int periodic = 0; periodic < 3; ++periodic) {
    Domain d;
    d.lower = Vec3::Zero();
    d.upper = Vec3(12, 9, 10);
    d.periodic = {periodic >= 1, periodic >= 1, periodic == 2};
    Rng rng(7 + periodic);
    std::vector<Vec3> r;
    std::vector<double> a;
    for (int i = 0; i < 3000; ++i) {
      a.push_back(i % 50 == 0 ? 0.5 : 0.05);  // 1:10, 2 % large
      r.push_back(Vec3(rng.uniform() * 12, rng.uniform() * 9, rng.uniform() * 10));
    }
    NeighbourList list(d, 0.05);
    list.build(r, a, {});
    const auto oracle = NeighbourList::brute_force(d, 0.05, r, a);
    ASSERT_EQ(list.pairs().size(), oracle.size());
    for (std::size_t k = 0; k < oracle.size(); ++k) {
      EXPECT_EQ(list.pairs()[k].owner, oracle[k].owner);
      EXPECT_EQ(list.pairs()[k].partner, oracle[k].partner);
    }
    EXPECT_GT(oracle.size(), 100u) << "the case must have pairs to find";
  }
}

// Elastic gas at phi = 0.1 with stiff springs (m = d = T = 1: 864 spheres, linear contacts
// of duration 2e-3, 0.35 % of the mean free time 0.57): the collision frequency (contacts begun)
// against Enskog–Carnahan–Starling, 1.764 per particle (tests/VALIDATION.md, "Elastic hard-sphere
// gas"). About 1.5e4 pair collisions are counted (1 sigma 0.8 %); the finite contact time shortens
// free flights by ~0.2 %: tolerance 2 %. The total energy (kinetic + elastic) is conserved to a
// drift per collision below 1e-6 of the energy (velocity Verlet at t_c / 10).
TEST(SoftGas, ElasticCollisionFrequencyMatchesEnskog) {
  GranularGasSpec spec;
  spec.count = 1000;
  spec.volume_fraction = 0.1;
  spec.seed = 3;
  System system = make_granular_gas(spec);
  SoftSphereEngine sim(system, linear_gas_options(2e-3, 10));
  sim.run_until(3.0);  // about 5 collisions per particle: the FCC start forgotten
  const double energy0 = sim.energies().total();
  const std::uint64_t start = sim.statistics().pair_events;
  const double t_start = sim.time(), span = 20.0;
  sim.run_until(t_start + span);
  const double collisions = static_cast<double>(sim.statistics().pair_events - start);
  const double n = static_cast<double>(sim.particle_count());  // 864: the FCC start's 4 x 6^3
  const double rate = 2.0 * collisions / (n * span);
  const double enskog = test::enskog_collision_rate(n / sim.system().domain.volume(), 1.0, 0.1, 1.0, 1.0);
  EXPECT_NEAR(enskog, 1.76454, 1e-4) << "VALIDATION.md's value";
  std::printf("soft gas: %.0f collisions, rate %.4f, Enskog %.4f, ratio %.4f, T = %.5f\n", collisions, rate,
              enskog, rate / enskog, temperature(sim));
  EXPECT_NEAR(rate / enskog, 1.0, 0.02);
  const double drift = std::abs(sim.energies().total() - energy0) / energy0;
  std::printf("energy drift %.3e over %.0f collisions\n", drift, collisions);
  EXPECT_LT(drift / collisions, 1e-6);
}

// Homogeneous cooling at e = 0.9 (the hard-sphere test's gas: 500 spheres, phi = 0.1)
// (3 runs) against Haff's law, T(t0) = T0 / 4 with t0 = 17.8964 (tests/VALIDATION.md, "Homogeneous
// cooling"), for the soft spheres with contacts of 2e-3 at t_c / 50 (the restitution is then right
// to 1e-3, so 1 - e^2 to 1 %). Tolerance 4 % as in the hard-sphere test (statistics ~1 %,
// finite-density effects 1-3 %).
TEST(SoftGas, CoolingFollowsHaff) {
  const double e = 0.9, t0 = 17.8964;
  double ratio = 0;
  const int runs = 3;
  for (int run = 0; run < runs; ++run) {
    GranularGasSpec spec;
    spec.count = 500;
    spec.volume_fraction = 0.1;
    spec.seed = 100 + run;
    SoftSphereEngine elastic(make_granular_gas(spec), linear_gas_options(2e-3, 50));
    elastic.run_until(3.0);
    const double temperature0 = temperature(elastic);
    // Continue with e = 0.9: the state handed over through a checkpoint group.
    const std::string path = testing::TempDir() + "soft_cooling_" + std::to_string(getpid()) + ".h5";
    {
      h5::File f = h5::File::create(path);
      elastic.save_state(f.create_group("state"));
    }
    spec.restitution = e;
    h5::File f = h5::File::open(path, false);
    SoftSphereEngine sim(make_granular_gas(spec), linear_gas_options(2e-3, 50), f.open_group("state"));
    sim.run_until(sim.time() + t0);
    const double measured = temperature(sim) / (temperature0 / 4.0);
    std::printf("run %d: T(t0) / T_Haff = %.4f\n", run, measured);
    ratio += measured / runs;
  }
  EXPECT_NEAR(ratio, 1.0, 0.04);
}

/// A column of spheres (1 mm glass, e = 0.3) dropped from a lattice into a box
/// with walls, settled under gravity.
System column(double mu_walls, int nx, int nz) {
  System s;
  const double d = 1e-3, side = nx * 1.2e-3;
  s.domain.lower = Vec3::Zero();
  s.domain.upper = Vec3(side, side, 0.05);
  s.species.push_back(Species{"glass", d, 2500, false});
  s.walls = box_walls(s.domain);
  ContactLaw pair, wall;
  pair.restitution = wall.restitution = 0.3;
  pair.friction = 0.3;
  wall.friction = mu_walls;
  s.materials = MaterialTable(1, s.walls.size(), pair, wall);
  s.flight.gravity = Vec3(0, 0, -9.81);
  Rng rng(5);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i)
        s.add_particle(0, Vec3((i + 0.5) * 1.2e-3 + 1e-5 * rng.uniform(), (j + 0.5) * 1.2e-3 + 1e-5 * rng.uniform(),
                               (k + 0.5) * 1.2e-3 + 0.5e-3),
                       Vec3::Zero());
  return s;
}

// A packed column at rest: the floor carries the weight. Side walls without friction carry no
// vertical force, so the floor's force, averaged over 0.05 s of rest, is m g N; at rest the
// time-average of the contact force equals the weight exactly, up to the residual motion's
// momentum change (below 1e-4 of the weight's impulse once settled): tolerance 0.1 %. With
// friction on the side walls (Janssen) the walls together still carry the weight.
TEST(SoftColumn, FloorCarriesTheWeightAtRest) {
  for (double mu_walls : {0.0, 0.5}) {
    System s = column(mu_walls, 5, 8);
    const double weight = 200 * s.species[0].mass() * 9.81;
    SoftSphereOptions o = hertz_options(1e7, 0.3, 0.0);
    o.max_overlap = 0.1;
    SoftSphereEngine sim(s, o);
    sim.run_until(0.15);
    const RunStatistics before = sim.statistics();
    sim.run_until(0.20);
    const RunStatistics& after = sim.statistics();
    Vec3 walls_total = Vec3::Zero();
    for (std::size_t w = 0; w < s.walls.size(); ++w)
      walls_total += (after.wall_impulse[w] - before.wall_impulse[w]) / 0.05;
    const std::size_t floor = 4;  // x_low, x_high, y_low, y_high, z_low, z_high
    ASSERT_EQ(s.walls[floor].name, "z_low");
    const double floor_force = -(after.wall_impulse[floor] - before.wall_impulse[floor]).z() / 0.05;
    std::printf("mu_walls %.1f: floor %.6f N, all walls %.6f N, weight %.6f N, KE %.3e J\n", mu_walls, floor_force,
                -walls_total.z(), weight, sim.energies().translational);
    if (mu_walls == 0.0) {
      EXPECT_NEAR(floor_force / weight, 1.0, 1e-3);
    } else {
      EXPECT_LT(floor_force / weight, 1.0 - 1e-3) << "the walls carry part of it (Janssen)";
    }
    EXPECT_NEAR(-walls_total.z() / weight, 1.0, 1e-3);
  }
}

// The step-size detector. Linear springs: velocity Verlet is stable for omega dt < 2, and the
// method refuses a step above that limit at the start and accepts one below it. Hertz springs
// stiffen with the overlap: a step that suits the impact speed the scene declares but not the
// real one blows up in the run, and the energy detector stops it, naming the step; the same
// scene at a safe step runs through.
TEST(SoftDetectors, StepAboveTheStabilityLimitIsCaught) {
  ContactLaw law;
  law.restitution = 0.9;
  System s = empty_system(1e-3, 2500, law, 1);
  s.add_particle(0, Vec3(0, 0, 0.5e-3 + 1e-6), Vec3(0, 0, -1));
  const double m = s.species[0].mass(), k = 1000;
  const double limit = 2.0 / std::sqrt(k / m);  // the wall contact: m* = m
  EXPECT_THROW(SoftSphereEngine(s, linear_options(k, 1.05 * limit)), std::invalid_argument);
  EXPECT_NO_THROW(SoftSphereEngine(s, linear_options(k, 0.95 * limit)));

  // Hertz: a gas of 200 spheres hitting at ~2 m/s, declared impact speed 1e-4 m/s.
  for (double factor : {0.3, 5.0}) {
    GranularGasSpec spec;
    spec.count = 200;
    spec.volume_fraction = 0.2;
    spec.diameter = 1e-3;
    spec.density = 2500;
    spec.temperature = 2500 * std::numbers::pi / 6 * 1e-9 * 1.0;  // 1 m/s per component
    spec.restitution = 0.9;
    SoftSphereOptions o = hertz_options(1e7, 0.3, 0.0);
    o.impact_speed = 1e-4;
    SoftSphereEngine probe(make_granular_gas(spec), o);
    const PairContact& c = probe.pair_contact(0, 0);
    const double safe = 2.0 / std::sqrt(c.stiffness_at(c.peak_overlap(4.0)) / c.reduced_mass);
    o.time_step = factor * safe;
    SoftSphereEngine sim(make_granular_gas(spec), o);
    bool fired = false;
    try {
      sim.run_until(2e-2);
    } catch (const MethodFailure& e) {
      fired = true;
      std::printf("factor %.1f: %s\n", factor, e.what());
    }
    EXPECT_EQ(fired, factor > 1.0) << "step " << factor << " x the limit at 4 m/s";
  }
}

// The overlap detector: a column under gravity on springs too soft for its weight sinks in
// beyond max_overlap and the run stops; stiff enough, it comes to rest.
TEST(SoftDetectors, StiffnessTooSmallForTheLoadIsCaught) {
  for (double young : {3e3, 1e7}) {
    System s = column(0.0, 3, 12);
    SoftSphereOptions o = hertz_options(young, 0.3, 0.0);
    o.max_overlap = 0.1;
    o.impact_speed = 0.5;
    SoftSphereEngine sim(s, o);
    bool fired = false;
    try {
      sim.run_until(0.12);
    } catch (const MethodFailure& e) {
      fired = true;
      EXPECT_EQ(e.status, "soft_sphere_overlap");
      std::printf("E = %.0e: %s\n", young, e.what());
    }
    EXPECT_EQ(fired, young < 1e4) << "E = " << young;
  }
}

/// Bit patterns of every position and velocity.
std::vector<std::uint64_t> bits(const CollisionMethod& sim) {
  std::vector<std::uint64_t> out;
  for (std::size_t i = 0; i < sim.particle_count(); ++i)
    for (const Vec3& v : {sim.position(i), sim.velocity(i), sim.spin(i)})
      for (int k = 0; k < 3; ++k) {
        std::uint64_t b;
        std::memcpy(&b, &v[k], sizeof b);
        out.push_back(b);
      }
  return out;
}

// Same system, same result bit for bit; a run saved and restored midway continues bit for bit
// (friction, walls, gravity: springs, contact histories and the Verlet list all in the state);
// stopping at a step boundary (stop_time: where the run loop ends its wall-clock chunks)
// changes nothing.
TEST(SoftDeterminism, RunsAndCheckpointsAreBitForBit) {
  System s = column(0.4, 5, 6);
  SoftSphereOptions o = hertz_options(1e7, 0.3, 0.0);
  o.rolling_friction = 0.05;
  SoftSphereEngine a(s, o), b(s, o);
  a.run_until(0.04);
  b.run_until(b.stop_time(0.013));
  b.run_until(b.stop_time(0.02));
  const std::string path = testing::TempDir() + "soft_resume_" + std::to_string(getpid()) + ".h5";
  {
    h5::File f = h5::File::create(path);
    b.save_state(f.create_group("state"));
  }
  h5::File f = h5::File::open(path, false);
  SoftSphereEngine c(s, o, f.open_group("state"));
  EXPECT_NE(b.time(), 0.02) << "a step boundary, not the time asked for";
  b.run_until(0.04);
  c.run_until(0.04);
  EXPECT_EQ(bits(a), bits(b));
  EXPECT_EQ(bits(a), bits(c));
  EXPECT_EQ(a.statistics().pair_events, c.statistics().pair_events);
  EXPECT_EQ(a.energies().dissipated, c.energies().dissipated);
  EXPECT_GT(a.statistics().pair_events, 50u);
}

// The energy books close: kinetic + potential + elastic + dissipated is constant to the
// integration error, which falls as dt^2 (a dropped column with friction, damping and rolling
// resistance: at the default step, t_c / 50, the error must be below 1e-3 of the energy
// dissipated, and four times smaller than at t_c / 25, within 50 %).
TEST(SoftEnergy, BooksCloseToTheIntegrationError) {
  double error[2];
  int k = 0;
  for (double fraction : {0.04, 0.02}) {
    System s = column(0.3, 5, 6);
    SoftSphereOptions o = hertz_options(1e7, 0.3, 0.0);
    o.step_fraction = fraction;
    o.rolling_friction = 0.05;
    SoftSphereEngine sim(s, o);
    const double start = sim.energies().total();
    sim.run_until(0.05);
    error[k++] = std::abs(sim.energies().total() - start) / sim.energies().dissipated;
    std::printf("step fraction %.3f: energy error %.3e of the dissipated %.3e J\n", fraction, error[k - 1],
                sim.energies().dissipated);
  }
  EXPECT_LT(error[1], 1e-3);
  EXPECT_NEAR(error[0] / error[1], 4.0, 2.0);
}

}  // namespace
}  // namespace carom
