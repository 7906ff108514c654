// Inflow and outflow bookkeeping (events/flow/flow_boundaries.hpp): the mass that enters over
// any window against the set rate, a full slab's waiting particles, the outflow against a
// brute-force oracle, particle-seconds, ids, the same seed giving the same particles, and a
// checkpoint mid-run continuing bit for bit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "flow_test_support.hpp"

using namespace carom;
using namespace carom::flow_test;

namespace {

/// An outlet at the floor: centres below z = 0.005 leave.
Outflow floor_outlet() {
  return Outflow{"floor", 2, 0.005, -1};
}

/// Runs `steps` flow steps kStep apart from t = 0 with drift between them; calls
/// after(step, flow, particles) after each.
template <class After>
void run(FlowBoundaries& flow, ParticleStore& particles, int first, int steps, After&& after) {
  for (int k = first; k < first + steps; ++k) {
    const double time = k * kStep;
    ParticleChange change;
    flow.step(time, particles, change);
    apply(change, particles);
    after(k, flow, particles);
    drift(particles, kStep);
  }
}

}  // namespace

// Reference: the set rate. Entered mass at t is m floor(rate t / m) (one product, no sum), so
// over every window [t_i, t_j] of the run the mass in differs from rate (t_j - t_i) by less than
// one particle mass m: the tolerance is that bound, not a statistical one. 5.3 particles a step
// moving 1 m/s out of a 4 mm slab leave it free (volume fraction ~0.06), so none waits.
TEST(FlowBoundaries, MassInOverAnyWindowIsTheSetRateWithinOneParticle) {
  System system = duct();
  const double per_second = 5300.0;
  const Inflow in = top_inflow(system, per_second);
  FlowBoundaries flow({in}, {floor_outlet()}, system, 11, 0.0, kStep);
  ParticleStore particles;
  std::vector<double> time, mass;
  run(flow, particles, 0, 600, [&](int k, const FlowBoundaries& f, const ParticleStore&) {
    time.push_back(k * kStep);
    mass.push_back(f.inflow_counters(0).entered_mass);
  });
  const double m = system.species[0].mass();
  double worst = 0.0;
  for (std::size_t i = 0; i < time.size(); i += 7)
    for (std::size_t j = i + 1; j < time.size(); ++j)
      worst = std::max(worst, std::abs(mass[j] - mass[i] - in.mass_flow * (time[j] - time[i])));
  EXPECT_LT(worst, m);
  EXPECT_EQ(flow.inflow_counters(0).blocked_steps, 0u);
  EXPECT_EQ(flow.inflow_counters(0).waiting(), 0u);
  EXPECT_EQ(flow.blocked_message(0), "");
  EXPECT_GT(worst, 0.5 * m) << "the windows should see the fractional remainder";
  // Particles cross 8.5 cm in 85 steps: the outflow takes them all but those still on the way.
  const OutflowCounters& out = flow.outflow_counters(0);
  EXPECT_EQ(out.left + particles.size(), flow.inflow_counters(0).entered);
  EXPECT_EQ(flow.present_total(), particles.size());
}

// A slab holding beads that never move fills: the particles owed beyond what fits wait
// (waiting() = floor(rate t / m) - entered, computed here independently), the blocked steps and
// failed tries are counted, and each step ends (attempts bound the tries).
TEST(FlowBoundaries, FullSlabReportsTheWaitingParticles) {
  System system = duct();
  Inflow in = top_inflow(system, 200000.0);  // 200 a step into a slab that holds ~50
  in.velocity = Vec3::Zero();
  in.attempts = 50;
  FlowBoundaries flow({in}, {}, system, 3, 0.0, kStep);
  ParticleStore particles;
  const double m = system.species[0].mass();
  for (int k = 1; k <= 20; ++k) {
    ParticleChange change;
    flow.step(k * kStep, particles, change);
    apply(change, particles);  // no drift: the beads stay in the slab
    const InflowCounters& c = flow.inflow_counters(0);
    const double due = std::floor(in.mass_flow * (k * kStep) / m);
    EXPECT_EQ(static_cast<double>(c.waiting()), due - static_cast<double>(c.entered)) << k;
    EXPECT_EQ(c.entered, particles.size());
  }
  const InflowCounters& c = flow.inflow_counters(0);
  EXPECT_GT(c.waiting(), 3000u);
  EXPECT_EQ(c.blocked_steps, 20u);
  EXPECT_GE(c.failed_tries, 20u * 50u);
  EXPECT_GT(c.entered, 20u) << "the slab takes some";
  const std::string message = flow.blocked_message(0);
  EXPECT_NE(message.find("inflow \"top\" found its slab full at 20 flow step(s)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(std::to_string(c.waiting()) + " particle(s) still wait"),
            std::string::npos)
      << message;
}

// Reference: brute force, each particle against each outlet. The flow step's removals are the
// particles beyond any outlet, ascending and once each; each is booked to the first outlet it
// is beyond (count and mass); particle-seconds are the counts before the change times the step.
TEST(FlowBoundaries, OutflowTakesExactlyTheParticlesBeyondAPlane) {
  System system = duct();
  system.species.push_back(Species{"fine", 1e-3, 1000.0});
  const std::vector<Outflow> outlets{
      {"floor", 2, 0.02, -1}, {"side", 0, 0.015, 1}, {"top", 2, 0.08, 1}, {"corner", 2, 0.03, -1}};
  Rng rng(5);
  ParticleStore particles;
  for (int i = 0; i < 2000; ++i) {
    const std::uint32_t s = rng.uniform() < 0.3 ? 1 : 0;
    const Species& kind = system.species[s];
    const Vec3 r(rng.uniform(0.0, 0.02), rng.uniform(0.0, 0.02), rng.uniform(0.0, 0.1));
    particles.add(r, rng.normal3(), rng.normal3(), kind.radius(), kind.mass(), kind.inertia(), s,
                  1000 + i);
  }
  system.particles = particles;
  FlowBoundaries flow({}, outlets, system, 1, 0.5, kStep);
  ParticleChange change;
  flow.step(0.75, particles, change);

  std::vector<std::size_t> expected;
  std::vector<std::uint64_t> left(outlets.size(), 0);
  std::vector<double> left_mass(outlets.size(), 0.0);
  double seconds[2] = {0.0, 0.0}, energy_out = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    seconds[particles.species[i]] += 0.25;
    const double x = particles.position[i].x(), z = particles.position[i].z();
    const bool beyond[4] = {z<0.02, x> 0.015, z > 0.08, z < 0.03};
    for (int k = 0; k < 4; ++k)
      if (beyond[k]) {
        expected.push_back(i);
        ++left[k];
        left_mass[k] += particles.mass[i];
        // Kinetic (translational, rotational) and potential energy, g = -9.81 m/s^2 along z.
        energy_out += 0.5 * particles.mass[i] * particles.velocity[i].squaredNorm() +
                      0.5 * particles.inertia[i] * particles.spin[i].squaredNorm() +
                      particles.mass[i] * 9.81 * z;
        break;
      }
  }
  EXPECT_EQ(change.removed, expected);
  EXPECT_EQ(change.added.size(), 0u);
  EXPECT_GT(left[3], 0u) << "the test should have particles beyond two outlets";
  for (std::size_t k = 0; k < outlets.size(); ++k) {
    EXPECT_EQ(flow.outflow_counters(k).left, left[k]) << k;
    EXPECT_DOUBLE_EQ(flow.outflow_counters(k).left_mass, left_mass[k]) << k;
  }
  for (int s = 0; s < 2; ++s) EXPECT_DOUBLE_EQ(flow.particle_seconds()[s], seconds[s]);
  // Summed in another order: equal to round-off (1e-12 relative).
  EXPECT_NEAR(flow.energy_out(), energy_out, 1e-12 * energy_out);
  EXPECT_EQ(flow.energy_in(), 0.0);
  // After the change: the counts that stay, and the integral continued with them.
  std::uint64_t stay[2] = {0, 0};
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (!std::binary_search(expected.begin(), expected.end(), i)) ++stay[particles.species[i]];
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(flow.present()[s], stay[s]);
    EXPECT_DOUBLE_EQ(flow.particle_seconds_at(1.0)[s], seconds[s] + 0.25 * stay[s]);
  }
}

// New particles get ids from 1 + the largest id ever seen (among the system's particles and
// every store stepped since), never one in use; clock = the step's time, zero spin, species
// properties.
TEST(FlowBoundaries, NewParticlesHaveFreshIdsAndTheSpeciesProperties) {
  System system = duct();
  const Species& kind = system.species[0];
  system.add_particle(0, Vec3(0.01, 0.01, 0.05), Vec3::Zero());
  system.particles.id[0] = 41;
  FlowBoundaries flow({top_inflow(system, 5000.0)}, {}, system, 2, 0.0, kStep);
  EXPECT_EQ(flow.next_id(), 42u);
  ParticleStore particles = system.particles;
  particles.id[0] = 99;  // a method may renumber; ids seen at a step count too
  std::set<std::uint64_t> seen{99};
  std::uint64_t entered = 0;
  double energy_in = 0.0;
  run(flow, particles, 1, 10, [&](int k, const FlowBoundaries& f, const ParticleStore& p) {
    const std::set<std::uint64_t> ids(p.id.begin(), p.id.end());
    EXPECT_EQ(ids.size(), p.size()) << "an id is used twice";
    const std::uint64_t largest_before = *seen.rbegin();
    std::uint64_t fresh = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (seen.count(p.id[i])) continue;
      ++fresh;
      EXPECT_GT(p.id[i], largest_before);
      EXPECT_EQ(p.clock[i], k * kStep);
      EXPECT_EQ(p.spin[i], Vec3::Zero());
      EXPECT_EQ(p.radius[i], kind.radius());
      EXPECT_EQ(p.mass[i], kind.mass());
      EXPECT_EQ(p.inertia[i], kind.inertia());
      energy_in +=
          0.5 * p.mass[i] * p.velocity[i].squaredNorm() + p.mass[i] * 9.81 * p.position[i].z();
    }
    EXPECT_EQ(fresh, f.inflow_counters(0).entered - entered);
    entered = f.inflow_counters(0).entered;
    seen.insert(ids.begin(), ids.end());
  });
  EXPECT_EQ(seen.size(), 1 + flow.inflow_counters(0).entered);
  EXPECT_NEAR(flow.energy_in(), energy_in, 1e-12 * energy_in);
}

// Same seed, same particles bit for bit; another seed, other particles.
TEST(FlowBoundaries, SameSeedGivesTheSameParticlesBitForBit) {
  System system = duct();
  Inflow in = top_inflow(system, 4321.0);
  in.velocity_spread = Vec3(0.1, 0.2, 0.3);
  const auto history = [&](std::uint64_t seed) {
    FlowBoundaries flow({in}, {floor_outlet()}, system, seed, 0.0, kStep);
    ParticleStore particles;
    run(flow, particles, 0, 200, [](int, const FlowBoundaries&, const ParticleStore&) {});
    return particles;
  };
  const ParticleStore a = history(8), b = history(8), c = history(9);
  EXPECT_GT(a.size(), 300u);
  EXPECT_TRUE(identical(a, b));
  EXPECT_FALSE(identical(a, c));
}

// A checkpoint mid-run (save, then restore into a FlowBoundaries built from scratch) continues
// bit for bit: the particles and every counter equal those of the run without the break.
TEST(FlowBoundaries, SaveAndRestoreMidRunContinuesBitForBit) {
  namespace fs = std::filesystem;
  const fs::path file =
      fs::temp_directory_path() / ("carom_flow_state_" + std::to_string(::getpid()) + ".h5");
  System system = duct();
  Inflow in = top_inflow(system, 7777.0);
  in.velocity_spread = Vec3(0.05, 0.05, 0.2);
  const std::vector<Outflow> out{floor_outlet()};
  const auto noop = [](int, const FlowBoundaries&, const ParticleStore&) {};

  FlowBoundaries whole({in}, out, system, 21, 0.0, kStep);
  ParticleStore p_whole;
  run(whole, p_whole, 0, 300, noop);

  ParticleStore p_split;
  {
    FlowBoundaries first({in}, out, system, 21, 0.0, kStep);
    run(first, p_split, 0, 137, noop);
    h5::File f = h5::File::create(file.string());
    first.save(f.create_group("flow"));
  }
  FlowBoundaries second({in}, out, system, 999, 5.0, kStep);  // seed and start come back
  {
    h5::File f = h5::File::open(file.string(), false);
    second.restore(f.open_group("flow"));
  }
  fs::remove(file);
  run(second, p_split, 137, 163, noop);

  EXPECT_TRUE(identical(p_whole, p_split));
  const InflowCounters &a = whole.inflow_counters(0), &b = second.inflow_counters(0);
  EXPECT_EQ(a.entered, b.entered);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(a.owed), std::bit_cast<std::uint64_t>(b.owed));
  EXPECT_EQ(a.entered_mass, b.entered_mass);
  EXPECT_EQ(whole.outflow_counters(0).left, second.outflow_counters(0).left);
  EXPECT_EQ(whole.outflow_counters(0).left_mass, second.outflow_counters(0).left_mass);
  EXPECT_EQ(whole.particle_seconds(), second.particle_seconds());
  EXPECT_EQ(whole.energy_in(), second.energy_in());
  EXPECT_EQ(whole.energy_out(), second.energy_out());
  EXPECT_EQ(whole.next_id(), second.next_id());
  EXPECT_EQ(whole.present(), second.present());
}

// A checkpoint of other inflows is refused with a message naming them.
TEST(FlowBoundaries, RestoreRefusesAnotherScenesFlows) {
  namespace fs = std::filesystem;
  const fs::path file =
      fs::temp_directory_path() / ("carom_flow_other_" + std::to_string(::getpid()) + ".h5");
  System system = duct();
  Inflow in = top_inflow(system, 1000.0);
  {
    FlowBoundaries flow({in}, {}, system, 1, 0.0, kStep);
    h5::File f = h5::File::create(file.string());
    flow.save(f.create_group("flow"));
  }
  in.name = "other";
  FlowBoundaries flow({in}, {}, system, 1, 0.0, kStep);
  h5::File f = h5::File::open(file.string(), false);
  try {
    flow.restore(f.open_group("flow"));
    ADD_FAILURE() << "restored another scene's inflows";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("\"top\""), std::string::npos) << e.what();
  }
  fs::remove(file);
}

// The particles leaving at a step are no obstacles to those entering at it: a 1.8 cm bead whose
// centre is just beyond the outlet at the slab's upper face covers the middle of the slab.
// With the outlet, new beads take that room (some overlap the leaving bead); without it, none
// does (it stays, so it is an obstacle).
TEST(FlowBoundaries, LeavingParticlesAreNoObstacles) {
  for (const bool with_outlet : {true, false}) {
    System system = duct();
    system.species.push_back(Species{"ball", 0.018, 100.0});
    system.add_particle(1, Vec3(0.01, 0.01, 0.0901), Vec3::Zero());
    const Inflow in = top_inflow(system, 300000.0);
    std::vector<Outflow> out;
    if (with_outlet) out.push_back(Outflow{"top", 2, 0.09, 1});
    FlowBoundaries flow({in}, out, system, 12, 0.0, kStep);
    ParticleChange change;
    flow.step(kStep, system.particles, change);
    EXPECT_EQ(change.removed.size(), with_outlet ? 1u : 0u);
    int overlapping = 0;
    for (std::size_t j = 0; j < change.added.size(); ++j)
      overlapping += (change.added.position[j] - system.particles.position[0]).norm() <
                     change.added.radius[j] + system.particles.radius[0];
    if (with_outlet)
      EXPECT_GT(overlapping, 5);
    else
      EXPECT_EQ(overlapping, 0);
  }
}
