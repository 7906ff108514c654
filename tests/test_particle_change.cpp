// Particles leaving and entering a running method (ParticleChange, events/method.hpp): the
// removal and insertion of inflow and outflow, in every method.
//
// The scene is a small cloud (tests/test_tagged_bodies.cpp): a 1.5 mm sphere at 0.5 m/s in a
// periodic 6 x 6 x 9 mm box of 0.3 mm glass at solid fraction 0.05, no gravity, e = 0.7,
// mu = 0.3. At t1 a synchronising action removes every fifth glass particle and puts a new one
// (fresh id, reversed and halved velocity) where each removed one was, so the new ones overlap
// nothing the old ones did not.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "events/method_factory.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {
namespace {

std::string cloud(const std::string& method, double glass_rms = 0.0) {
  return "[domain]\nmin = [0, 0, 0]\nmax = [0.006, 0.006, 0.009]\nperiodic = [\"x\", \"y\", "
         "\"z\"]\n"
         "[[species]]\nname = \"sphere\"\ndiameter = 1.5e-3\ndensity = 500.0\nyoung_modulus = 1e7\n"
         "[[species]]\nname = \"glass\"\ndiameter = 0.3e-3\ndensity = 2500.0\nyoung_modulus = 1e7\n"
         "fill = { volume_fraction = 0.05 }\n"
         "[[particles]]\nspecies = \"sphere\"\nposition = [0.003, 0.003, 0.004]\n"
         "velocity = [0.1, 0, 0.5]\ntagged = true\n"
         "[collisions]\ndefault = { e = 0.7, mu = 0.3, beta0 = 0.34 }\n"
         "[method]\nkind = \"" +
         method + "\"\n[initial]\nseed = 3\nrms_velocity = " + std::to_string(glass_rms) +
         "\n[time]\nend = 0.01\n";
}

constexpr double kChangeTime = 0.002;  // s
constexpr std::uint64_t kFirstNewId = 1000000;

/// Every fifth glass particle leaves; a new one with -v/2 takes its place.
void swap_some_glass(GlobalStep& step) {
  const ParticleStore& p = step.particles;
  std::uint64_t next_id = kFirstNewId;
  std::size_t glass = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.species[i] != 1 || glass++ % 5 != 0) continue;
    step.change.removed.push_back(i);
    step.change.added.add(p.position[i], -0.5 * p.velocity[i], Vec3::Zero(), p.radius[i], p.mass[i],
                          p.inertia[i], 1, next_id++, step.time);
  }
}

struct Built {
  Scene scene;
  std::unique_ptr<CollisionMethod> sim;
};

Built build(const std::string& method, double glass_rms = 0.0) {
  Built b{parse_scene(cloud(method, glass_rms), "cloud.toml"), nullptr};
  build_initial_state(b.scene);
  b.sim = make_method(b.scene.system, b.scene.method);
  b.sim->tag_bodies(b.scene.analysis.tagged_bodies);
  return b;
}

std::size_t index_of(const CollisionMethod& sim, std::uint64_t id) {
  const auto& ids = sim.system().particles.id;
  return static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
}

class ChangeMethods : public ::testing::TestWithParam<std::string> {};

// The change itself: the removed ids are gone, the others keep their order, the new ones are
// appended in the given order with their states; the energy books close across it, because the
// energy the new particles bring minus what the old took is booked as flow (Energies::flow):
// total() just before and just after the step agree to round-off (1e-12 of the kinetic energy:
// a sum of ~1000 terms, each rounded once), while the kinetic energy itself changes by ~15 %.
TEST_P(ChangeMethods, ParticlesLeaveAndEnterAndTheBooksClose) {
  Built b = build(GetParam());
  CollisionMethod& sim = *b.sim;
  std::vector<std::uint64_t> before_ids;
  double total_before = 0, kinetic_before = 0;
  std::size_t removed = 0, added = 0;
  sim.add_synchronising_action("flow_step", kChangeTime, 1.0, [&](GlobalStep& step) {
    before_ids = step.particles.id;
    const Energies e = sim.energies();
    total_before = e.total();
    kinetic_before = e.translational + e.rotational;
    swap_some_glass(step);
    removed = step.change.removed.size();
    added = step.change.added.size();
  });
  // Actions at one time fire in the order they were added: this one sees the changed run.
  Energies after;
  std::vector<std::uint64_t> ids;
  sim.add_periodic_action("probe", kChangeTime, 1.0, [&] {
    after = sim.energies();
    ids = sim.system().particles.id;
  });
  sim.run_until(kChangeTime + 1e-6);
  ASSERT_GT(removed, 30u);
  ASSERT_EQ(sim.particle_count(), before_ids.size() - removed + added);
  EXPECT_NEAR(after.total(), total_before, 1e-12 * kinetic_before);
  EXPECT_GT(std::abs(after.translational + after.rotational - kinetic_before),
            0.01 * kinetic_before);
  EXPECT_NE(after.flow, 0.0);
  // Order: the survivors as before, then the new ones.
  std::vector<std::uint64_t> survivors(ids.begin(), ids.end() - static_cast<std::ptrdiff_t>(added));
  std::vector<std::uint64_t> expected;
  for (std::uint64_t id : before_ids)
    if (std::find(survivors.begin(), survivors.end(), id) != survivors.end())
      expected.push_back(id);
  EXPECT_EQ(survivors, expected);
  for (std::size_t k = 0; k < added; ++k) EXPECT_EQ(ids[survivors.size() + k], kFirstNewId + k);
  // And the run goes on.
  EXPECT_TRUE(sim.run_until(0.004));
  EXPECT_EQ(sim.particle_count(), before_ids.size() - removed + added);
}

// The tagged sphere keeps its books while the particles before it in the method's order leave
// (its index moves): the impulse booked over the whole run is its momentum change, to the
// tolerance of TaggedMethods.ImpulseIsTheMomentumChange (1e-11 of m |v0|, why: there).
TEST_P(ChangeMethods, TaggedBodyKeepsItsBooks) {
  Built b = build(GetParam());
  CollisionMethod& sim = *b.sim;
  const std::size_t start_index = index_of(sim, 0);
  const double m = sim.system().particles.mass[start_index];
  const Vec3 v0 = sim.velocity(start_index);
  sim.add_synchronising_action("flow_step", kChangeTime, 1.0, swap_some_glass);
  sim.run_until(0.006);
  const std::size_t end_index = index_of(sim, 0);
  ASSERT_LT(end_index, sim.particle_count());
  const Vec3 change = m * (sim.velocity(end_index) - v0);
  EXPECT_GT(change.norm(), 0.1 * m * v0.norm());
  EXPECT_LT((sim.statistics().tagged.total(0) - change).norm(), 1e-11 * m * v0.norm());
}

INSTANTIATE_TEST_SUITE_P(AllMethods, ChangeMethods,
                         ::testing::Values("event_driven", "soft_sphere", "monte_carlo"),
                         [](const auto& info) { return info.param; });

// The oracle of the event-driven change: going on after the change is the same as starting a
// fresh engine from the changed particles at t1 (which orders them in space, builds its own
// grid and predicts everything from scratch). Hard spheres are chaotic, so the comparison is
// short: 1 ms after the change (about one collision per glass particle), every particle's
// position agrees to 1e-12 m (the two runs differ by round-off in the order of equal-time work,
// which grows by ~10 per collision from 1e-19 m; measured: they agree bit for bit).
TEST(ChangeEventDriven, GoingOnEqualsAFreshStart) {
  Built b = build("event_driven", 0.3);
  b.sim->add_synchronising_action("flow_step", kChangeTime, 1.0, swap_some_glass);
  System fresh_system;
  b.sim->add_periodic_action("copy", kChangeTime, 1.0, [&] {
    fresh_system = b.sim->system();
    for (std::size_t i = 0; i < fresh_system.particles.size(); ++i) {
      fresh_system.particles.position[i] = b.sim->position(i);
      fresh_system.particles.velocity[i] = b.sim->velocity(i);
      fresh_system.particles.clock[i] = kChangeTime;
    }
  });
  b.sim->run_until(kChangeTime + 1e-9);
  ASSERT_GT(fresh_system.particles.size(), 0u);
  std::unique_ptr<CollisionMethod> fresh = make_method(fresh_system, b.scene.method);
  const double t2 = kChangeTime + 0.001;
  b.sim->run_until(t2);
  fresh->run_until(t2);
  ASSERT_EQ(fresh->particle_count(), b.sim->particle_count());
  std::map<std::uint64_t, Vec3> where;
  for (std::size_t i = 0; i < fresh->particle_count(); ++i)
    where[fresh->system().particles.id[i]] = fresh->position(i);
  double worst = 0;
  for (std::size_t i = 0; i < b.sim->particle_count(); ++i) {
    Vec3 d = b.sim->position(i) - where.at(b.sim->system().particles.id[i]);
    b.sim->system().domain.minimum_image(d);
    worst = std::max(worst, d.norm());
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(b.sim->statistics().pair_collisions[3], 300u);  // glass-glass collisions happened
}

}  // namespace
}  // namespace carom
