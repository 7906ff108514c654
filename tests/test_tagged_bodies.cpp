// Tagged bodies (events/tagged_impulses.hpp, scenarios/analysis/tagged_bodies.hpp): the
// collision impulse booked on a body is exactly what changed its momentum, in every method; the
// parts by partner add up to it and match the partners' own momentum change; the whole system's
// momentum is conserved to round-off where nothing outside the particles acts (a periodic box);
// the books resume bit for bit from a checkpoint; the drag fit recovers k from synthetic data.
//
// The scene is a small cloud_drag.toml: a 1.5 mm sphere (500 kg/m^3, 0.5 m/s) in a periodic
// 6 x 6 x 9 mm box of 0.3 mm glass at solid fraction 0.05 (about 1100 spheres), no gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "core/hdf5.hpp"
#include "events/method_factory.hpp"
#include "scenarios/analysis/drag_fit.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {
namespace {

/// The small cloud with the given method and box walls along z (or periodic everywhere).
std::string cloud_scene(const std::string& method, bool z_walls, double speed = 0.5) {
  // With walls the sphere starts 0.1 mm below the upper one (no cloud sphere fits between), and
  // the material is stiffer (cloud spheres caught between the sphere and a wall carry its load).
  const std::string young = z_walls ? "1e8" : "1e7";
  return std::string("[domain]\nmin = [0, 0, 0]\nmax = [0.006, 0.006, 0.009]\n") +
         (z_walls ? "periodic = [\"x\", \"y\"]\n" : "periodic = [\"x\", \"y\", \"z\"]\n") +
         "[[species]]\nname = \"sphere\"\ndiameter = 1.5e-3\ndensity = 500.0\nyoung_modulus = " +
         young +
         "\n[[species]]\nname = \"glass\"\ndiameter = 0.3e-3\ndensity = 2500.0\nyoung_modulus = " +
         young +
         "\n"
         "fill = { volume_fraction = 0.05 }\n"
         "[[particles]]\nspecies = \"sphere\"\nposition = [0.003, 0.003, " +
         (z_walls ? "0.00815" : "0.004") + "]\nvelocity = [0.1, 0, " + std::to_string(speed) +
         "]\ntagged = true\n"
         "[collisions]\ndefault = { e = 0.7, mu = 0.3, beta0 = 0.34 }\n"
         "[method]\nkind = \"" +
         method +
         "\"\n"
         "[initial]\nseed = 3\n[time]\nend = 0.01\n";
}

std::unique_ptr<CollisionMethod> build(Scene& scene) {
  build_initial_state(scene);
  std::unique_ptr<CollisionMethod> sim = make_method(scene.system, scene.method);
  sim->tag_bodies(scene.analysis.tagged_bodies);
  return sim;
}

/// Method index of particle id 0 (the listed sphere).
std::size_t index_of_sphere(const CollisionMethod& sim) {
  for (std::size_t i = 0; i < sim.particle_count(); ++i)
    if (sim.system().particles.id[i] == 0) return i;
  ADD_FAILURE() << "no particle with id 0";
  return 0;
}

/// Momentum of the particles of one species (all: species < 0), and the sum of m |v|, kg m/s.
std::pair<Vec3, double> momentum(const CollisionMethod& sim, int species = -1) {
  Vec3 p = Vec3::Zero();
  double scale = 0.0;
  const ParticleStore& s = sim.system().particles;
  for (std::size_t i = 0; i < sim.particle_count(); ++i) {
    if (species >= 0 && static_cast<int>(s.species[i]) != species) continue;
    p += s.mass[i] * sim.velocity(i);
    scale += s.mass[i] * sim.velocity(i).norm();
  }
  return {p, scale};
}

class TaggedMethods : public ::testing::TestWithParam<std::string> {};

// The scene key tags the listed sphere (id 0); the impulse booked on it over the run equals its
// momentum change, m (v - v0), to round-off: each collision changes v by J/m with one rounding,
// so after n collisions the two differ by about n eps m |v| (n ~ 100-1000 here: ~1e-13 of
// m |v0|); the tolerance 1e-11 of m |v0| leaves a margin and still fails on one lost or doubled
// collision (each carries ~1e-3 of the momentum). The parts by partner (glass, and the sphere's
// own species) add up to the total; in a periodic box the glass part is minus the glass cloud's
// momentum change (nothing else touches the cloud but itself and the sphere) and, for the
// methods with real partners (event-driven, soft spheres), the whole system's momentum is
// conserved to round-off: each collision or contact step conserves it to a rounding of its
// terms (~1e-16 relative), and 1e4 of them bound the drift by ~1e-12 of sum m |v|.
TEST_P(TaggedMethods, ImpulseIsTheMomentumChange) {
  Scene scene = parse_scene(cloud_scene(GetParam(), false), "cloud.toml");
  ASSERT_EQ(scene.analysis.tagged_bodies, std::vector<std::uint64_t>{0});
  std::unique_ptr<CollisionMethod> sim = build(scene);
  const std::size_t big = index_of_sphere(*sim);
  const double m = sim->system().particles.mass[big];
  const Vec3 v0 = sim->velocity(big);
  const auto [p_start, scale_start] = momentum(*sim);
  const auto [glass_start, glass_scale_start] = momentum(*sim, 1);
  sim->run_until(0.01);
  const TaggedImpulses& tagged = sim->statistics().tagged;
  ASSERT_EQ(tagged.body_count(), 1u);
  ASSERT_EQ(tagged.partners(), 2u);  // sphere, glass; no walls
  const Vec3 change = m * (sim->velocity(big) - v0);
  const Vec3 booked = tagged.total(0);
  EXPECT_GT(change.norm(), 0.1 * m * v0.norm()) << "the sphere must be slowed measurably";
  EXPECT_LT((booked - change).norm(), 1e-11 * m * v0.norm()) << GetParam();
  EXPECT_EQ(booked, tagged.impulse[0] + tagged.impulse[1]);
  const Vec3 glass_change = momentum(*sim, 1).first - glass_start;
  if (GetParam() != "monte_carlo") {
    EXPECT_LT((tagged.impulse[1] + glass_change).norm(), 1e-11 * m * v0.norm());
    const auto [p_end, scale_end] = momentum(*sim);
    EXPECT_LT((p_end - p_start).norm(), 1e-12 * (scale_start + scale_end)) << GetParam();
  }
}

// Walls: with walls across z and the sphere sent at the upper one, its wall part is booked too
// (nonzero), and all parts still add up to its momentum change.
TEST_P(TaggedMethods, WallImpulsesAreBooked) {
  Scene scene = parse_scene(cloud_scene(GetParam(), true, 1.0), "cloud.toml");
  std::unique_ptr<CollisionMethod> sim = build(scene);
  const std::size_t big = index_of_sphere(*sim);
  const double m = sim->system().particles.mass[big];
  const Vec3 v0 = sim->velocity(big);
  sim->run_until(0.004);
  const TaggedImpulses& tagged = sim->statistics().tagged;
  ASSERT_EQ(tagged.partners(), 4u);  // sphere, glass, z_low, z_high
  const std::size_t z_high = 2 + 1;
  EXPECT_LT(tagged.impulse[z_high].z(), -0.1 * m * v0.z())
      << "the upper wall pushed the sphere back";
  const Vec3 change = m * (sim->velocity(big) - v0);
  EXPECT_LT((tagged.total(0) - change).norm(), 1e-11 * m * v0.norm()) << GetParam();
}

/// The bits of every velocity and of the tagged books.
std::vector<double> state_bits(const CollisionMethod& sim) {
  std::vector<double> out;
  for (std::size_t i = 0; i < sim.particle_count(); ++i)
    for (double x : {sim.velocity(i).x(), sim.velocity(i).y(), sim.velocity(i).z()})
      out.push_back(x);
  for (const Vec3& j : sim.statistics().tagged.impulse)
    out.insert(out.end(), {j.x(), j.y(), j.z()});
  for (const Vec3& f : sim.statistics().tagged.step_force)
    out.insert(out.end(), {f.x(), f.y(), f.z()});
  return out;
}

// A run saved midway and restored (tagged again with the same ids, as `carom resume` does)
// continues bit for bit: the same velocities and the same books as the uninterrupted run.
TEST_P(TaggedMethods, BooksResumeBitForBit) {
  Scene scene = parse_scene(cloud_scene(GetParam(), false), "cloud.toml");
  std::unique_ptr<CollisionMethod> whole = build(scene);
  Scene again = parse_scene(cloud_scene(GetParam(), false), "cloud.toml");
  std::unique_ptr<CollisionMethod> first = build(again);
  whole->run_until(0.008);
  first->run_until(first->stop_time(0.003));
  const std::string path = testing::TempDir() + "tagged_resume_" + GetParam() + ".h5";
  {
    h5::File f = h5::File::create(path);
    first->save_state(f.create_group("state"));
  }
  h5::File f = h5::File::open(path, false);
  std::unique_ptr<CollisionMethod> resumed =
      restore_method(again.system, again.method, f.open_group("state"));
  resumed->tag_bodies(again.analysis.tagged_bodies);
  EXPECT_THROW(resumed->tag_bodies({1}), std::invalid_argument);
  resumed->run_until(0.008);
  const std::vector<double> a = state_bits(*whole), b = state_bits(*resumed);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << GetParam();
  EXPECT_GT(whole->statistics().tagged.total(0).norm(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(AllMethods, TaggedMethods,
                         ::testing::Values("event_driven", "soft_sphere", "monte_carlo"),
                         [](const auto& info) { return info.param; });

// Ids that are not particles, and repeats, are refused.
TEST(TaggedImpulses, RefusesUnknownAndRepeatedIds) {
  TaggedImpulses t;
  EXPECT_THROW(t.tag({5}, {0, 1, 2}, 1, 0), std::invalid_argument);
  TaggedImpulses u;
  EXPECT_THROW(u.tag({1, 1}, {0, 1, 2}, 1, 0), std::invalid_argument);
  TaggedImpulses v;
  v.tag({2, 0}, {0, 1, 2}, 2, 1);
  EXPECT_EQ(v.slot_of, (std::vector<std::int32_t>{1, -1, 0}));
  EXPECT_EQ(v.partners(), 3u);
}

// The fit of 1/V = 1/V0 + k t. Exact data: k and 1/V0 to round-off (1e-12 relative). Noisy data
// (Gaussian noise of standard deviation sigma on 1/V, 40 samples, 200 trials): the fitted k
// scatters about the true k by its standard error; the mean of (k_fit - k) / se over the trials
// is 0 within 4 / sqrt(200) (0.28), and the rms of that ratio is 1 within 0.15 (its sampling
// spread over 200 trials with t(38) tails is about 0.05).
TEST(DragFit, RecoversKFromSyntheticDecelerations) {
  const double v0 = 0.5, k = 80.0;
  std::vector<double> t, v;
  for (int i = 0; i <= 40; ++i) {
    t.push_back(5e-4 * i);
    v.push_back(1.0 / (1.0 / v0 + k * t.back()));
  }
  const InverseSpeedFit exact = fit_inverse_speed(t, v);
  ASSERT_TRUE(exact.valid);
  EXPECT_NEAR(exact.k, k, 1e-12 * k);
  EXPECT_NEAR(exact.intercept, 1.0 / v0, 1e-12 / v0);
  EXPECT_EQ(exact.points, 41u);

  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  double mean = 0.0, square = 0.0;
  const int trials = 200;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<double> noisy;
    for (double ti : t) noisy.push_back(1.0 / (1.0 / v0 + k * ti + noise(rng)));
    const InverseSpeedFit fit = fit_inverse_speed(t, noisy);
    ASSERT_TRUE(fit.valid);
    const double z = (fit.k - k) / fit.k_error;
    mean += z / trials;
    square += z * z / trials;
  }
  EXPECT_LT(std::abs(mean), 0.28);
  EXPECT_NEAR(std::sqrt(square), 1.0, 0.15);

  // Non-positive speeds (a body stopped or turned back) are left out; fewer than 3 points: invalid.
  EXPECT_EQ(fit_inverse_speed({0, 1, 2, 3}, {1.0, 0.5, 0.0, -0.1}).points, 2u);
  EXPECT_FALSE(fit_inverse_speed({0, 1, 2, 3}, {1.0, 0.5, 0.0, -0.1}).valid);
}

}  // namespace
}  // namespace carom
