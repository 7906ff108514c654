// Collision-frequency bookkeeping against a brute-force count: carom's RunStatistics (collisions
// per species pair, per species and wall) and the per-particle collision frequencies that the
// analysis layer reports in summary.json must equal, collision for collision, what a slow,
// obviously-correct O(N^2) event-driven code counts on the same small run.
//
// The oracle below shares no prediction, calendar, grid or collision code with carom: at every
// step it solves |dr + dv t| = R_i + R_j for every approaching pair and the flight to each of
// the six walls for every particle, takes the globally earliest event, moves every particle
// there and applies the normal restitution impulse. Smooth spheres (mu = 0, beta0 = -1), so
// spin never enters; no gravity, so flights are straight lines and contact times need only the
// quadratic.
//
// Why exact equality is the right check, and why the run is short: both codes follow the same
// exact trajectories but round differently (carom keeps delayed per-particle states and its
// own root formulas), so they differ by ~1e-16 at first. Hard-sphere dynamics is chaotic: each
// collision multiplies a perturbation by about (free path / diameter), so after a handful of
// collisions per particle the two runs would part and their counts would differ for reasons
// that have nothing to do with the bookkeeping. Measured here: the final positions differ by
// ~1e-11 of the box after 2 s, and the difference grows about tenfold per further 0.5 s (two
// more collisions per particle); at 2.5 s one of the ten cases already passes 1e-9. So the runs
// last 2 s (5-8 pair and 2-3 wall collisions per particle), and the final positions are
// compared too: agreeing to 1e-9 of the box (measured: 8e-11 at worst) shows that both codes
// processed the same sequence of collisions, so their counters must agree exactly. A collision
// missed, double-booked or booked to the wrong species or wall changes an integer count and
// fails the test (checked by swapping the low and high walls in the mapping, and by counting
// like collisions once in the frequency: both fail every case).
//
// The impacts (events/statistics.hpp: the collisions whose normal approach speed exceeds the
// scene's impact speed) are checked the same way: the oracle counts the collisions faster than
// kImpactSpeed, which is set near the middle of the approach speeds (T = 1 J, m = 1 kg and
// 0.3 kg: relative speeds of order 1-3 m/s), so that a wrong speed, sign or species in the
// impact test changes the counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "events/event_driven/engine.hpp"
#include "scenarios/analysis/run_analysis.hpp"
#include "scenarios/scene/scene.hpp"

namespace carom {
namespace {

constexpr int kSpecies = 2;
constexpr int kWalls = 6;
/// Oracle wall w lies on axis w / 2, at the low (w even) or high (w odd) end of the box.
const std::array<std::string, kWalls> kWallNames{"x_low",  "x_high", "y_low",
                                                 "y_high", "z_low",  "z_high"};
const std::array<std::string, kSpecies> kSpeciesNames{"large", "small"};

/// One smooth sphere of the brute-force oracle.
struct Ball {
  Vec3 position;  ///< m.
  Vec3 velocity;  ///< m/s.
  double radius;  ///< m.
  double mass;    ///< kg.
  int species;    ///< 0 or 1.
};

/// The scene's impact speed, m/s.
constexpr double kImpactSpeed = 1.0;

/// Collisions counted by the oracle.
struct Counts {
  std::array<std::array<std::uint64_t, kSpecies>, kSpecies> pair{};  ///< Symmetric, like carom's.
  std::array<std::array<std::uint64_t, kWalls>, kSpecies> wall{};    ///< [species][oracle wall].
  /// Of those, the impacts: normal approach speed above kImpactSpeed.
  std::array<std::array<std::uint64_t, kSpecies>, kSpecies> pair_impacts{};
  std::array<std::array<std::uint64_t, kWalls>, kSpecies> wall_impacts{};
  std::uint64_t pair_events = 0;
  std::uint64_t wall_events = 0;

  /// Collisions of species s with any wall.
  std::uint64_t walls(int s) const {
    std::uint64_t total = 0;
    for (std::uint64_t c : wall[s]) total += c;
    return total;
  }
};

/// Slow, obviously-correct event-driven hard-sphere dynamics in a closed box: O(N^2) work per
/// event, every particle moved at every event, constant normal restitution e for every pair
/// and wall, no friction, no gravity.
class BruteForceGas {
 public:
  BruteForceGas(std::vector<Ball> balls, const Vec3& lower, const Vec3& upper, double restitution)
      : balls_(std::move(balls)), lower_(lower), upper_(upper), restitution_(restitution) {}

  /// Processes every collision up to t_end (s) and moves every particle to t_end.
  void run_until(double t_end) {
    const std::size_t n = balls_.size();
    for (;;) {
      // The earliest event: a pair (i, j) or a particle i and a wall w.
      double earliest = std::numeric_limits<double>::infinity();
      std::size_t first = 0, second = 0;
      int wall = -1;
      for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
          const double t = contact_time(balls_[i], balls_[j]);
          if (t < earliest) earliest = t, first = i, second = j, wall = -1;
        }
        for (int w = 0; w < kWalls; ++w) {
          const double t = wall_time(balls_[i], w);
          if (t < earliest) earliest = t, first = i, wall = w;
        }
      }
      if (time_ + earliest > t_end) {
        move_all(t_end - time_);
        time_ = t_end;
        return;
      }
      move_all(earliest);
      time_ += earliest;
      if (wall < 0)
        collide_pair(balls_[first], balls_[second]);
      else
        collide_wall(balls_[first], wall);
    }
  }

  const std::vector<Ball>& balls() const { return balls_; }
  const Counts& counts() const { return counts_; }

 private:
  /// Time from now until spheres a and b touch, s: the smaller root of
  /// |dr + dv t|^2 = (R_a + R_b)^2, i.e. of |dv|^2 t^2 + 2 b t + c = 0 with b = dr . dv,
  /// c = |dr|^2 - (R_a + R_b)^2, for an approaching pair (dr . dv < 0); infinity otherwise.
  static double contact_time(const Ball& a, const Ball& b) {
    const Vec3 dr = a.position - b.position, dv = a.velocity - b.velocity;
    const double approach = dr.dot(dv);
    if (approach >= 0.0) return std::numeric_limits<double>::infinity();
    const double contact = a.radius + b.radius;
    const double gap2 = dr.squaredNorm() - contact * contact;
    const double discriminant = approach * approach - dv.squaredNorm() * gap2;
    if (discriminant < 0.0) return std::numeric_limits<double>::infinity();
    // The smaller root (-b - sqrt(D)) / |dv|^2, written as c / (-b + sqrt(D)) so that no two
    // nearly equal numbers are subtracted.
    return std::max(0.0, gap2 / (-approach + std::sqrt(discriminant)));
  }

  /// Time from now until sphere a touches wall w (moving towards it), s; infinity otherwise.
  double wall_time(const Ball& a, int w) const {
    const int axis = w / 2;
    const double v = a.velocity[axis];
    if (w % 2 == 0)
      return v < 0.0 ? std::max(0.0, (lower_[axis] + a.radius - a.position[axis]) / v)
                     : std::numeric_limits<double>::infinity();
    return v > 0.0 ? std::max(0.0, (upper_[axis] - a.radius - a.position[axis]) / v)
                   : std::numeric_limits<double>::infinity();
  }

  void move_all(double dt) {
    for (Ball& b : balls_) b.position += b.velocity * dt;
  }

  /// Normal restitution: J = -(1 + e) m_ab (dv . n) n on a, -J on b, n = (r_a - r_b) / |.|.
  void collide_pair(Ball& a, Ball& b) {
    const Vec3 n = (a.position - b.position).normalized();
    if (-(a.velocity - b.velocity).dot(n) > kImpactSpeed) {
      ++counts_.pair_impacts[a.species][b.species];
      if (a.species != b.species) ++counts_.pair_impacts[b.species][a.species];
    }
    const double reduced_mass = a.mass * b.mass / (a.mass + b.mass);
    const Vec3 impulse =
        -(1.0 + restitution_) * reduced_mass * (a.velocity - b.velocity).dot(n) * n;
    a.velocity += impulse / a.mass;
    b.velocity -= impulse / b.mass;
    ++counts_.pair[a.species][b.species];
    if (a.species != b.species) ++counts_.pair[b.species][a.species];
    ++counts_.pair_events;
  }

  /// A flat wall reverses the normal velocity component and scales it by e.
  void collide_wall(Ball& a, int w) {
    if (std::abs(a.velocity[w / 2]) > kImpactSpeed) ++counts_.wall_impacts[a.species][w];
    a.velocity[w / 2] *= -restitution_;
    ++counts_.wall[a.species][w];
    ++counts_.wall_events;
  }

  std::vector<Ball> balls_;
  Vec3 lower_, upper_;
  double restitution_;
  double time_ = 0.0;
  Counts counts_;
};

/// Box edge, m (solid fraction 0.105: dense enough for pair collisions to outnumber wall
/// collisions, dilute enough for random insertion). Species (d = 1 m, m = 1 kg) and
/// (d = 0.6 m, m = 0.3 kg): the mass ratio differs from the volume ratio, so a species mix-up
/// in the reduced mass changes the trajectories.
constexpr double kBox = 4.5;
constexpr int kPerSpecies = 15;
constexpr double kDiameter[kSpecies] = {1.0, 0.6};
constexpr double kMass[kSpecies] = {1.0, 0.3};

/// A scene with 2 x 15 listed particles at random non-overlapping places (random sequential
/// insertion, at least 1 % clearance to each other and the walls) and Maxwellian velocities
/// (T = 1 J), six walls, no gravity, e for every pair and wall, smooth, no collapse remedy.
std::string scene_text(std::uint64_t seed, double restitution, double end_time) {
  auto number = [](double x) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return std::string(buffer);
  };
  auto vector = [&](const Vec3& v) {
    return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]";
  };
  std::string text = "[domain]\nmin = [0.0, 0.0, 0.0]\nmax = " + vector(Vec3::Constant(kBox)) +
                     "\ngravity = [0.0, 0.0, 0.0]\n";
  for (int s = 0; s < kSpecies; ++s) {
    const double volume = std::numbers::pi / 6.0 * std::pow(kDiameter[s], 3);
    text += "[[species]]\nname = \"" + kSpeciesNames[s] + "\"\ndiameter = " + number(kDiameter[s]) +
            "\ndensity = " + number(kMass[s] / volume) + "\n";
  }
  text += "[collisions]\ndefault = { e = " + number(restitution) +
          ", mu = 0.0, beta0 = -1.0 }\ncollapse = { model = \"none\" }\n";
  text += "[time]\nend = " + number(end_time) + "\n";
  text += "[analysis]\nimpact_speed = " + number(kImpactSpeed) + "\n";
  Rng rng(seed);
  std::vector<std::pair<Vec3, double>> placed;  // centre, radius
  for (int k = 0; k < kSpecies * kPerSpecies; ++k) {
    const int s = k % kSpecies;
    const double radius = 0.5 * kDiameter[s];
    Vec3 r;
    for (bool free = false; !free;) {
      for (int axis = 0; axis < 3; ++axis)
        r[axis] = rng.uniform(1.01 * radius, kBox - 1.01 * radius);
      free = true;
      for (const auto& [centre, other] : placed)
        if ((r - centre).norm() < 1.01 * (radius + other)) free = false;
    }
    placed.emplace_back(r, radius);
    const Vec3 v = rng.normal3() / std::sqrt(kMass[s]);
    text += "[[particles]]\nspecies = \"" + kSpeciesNames[s] + "\"\nposition = " + vector(r) +
            "\nvelocity = " + vector(v) + "\n";
  }
  return text;
}

struct CountCase {
  double restitution;
  std::uint64_t seed;
};
/// How ctest lists a case (instead of its bytes).
void PrintTo(const CountCase& c, std::ostream* out) { *out << "e = " << c.restitution << ", seed " << c.seed; }

class CollisionCount : public ::testing::TestWithParam<CountCase> {};

// Run length 2 s: 5-8 pair and 2-3 wall collisions per particle (fewer at e = 0.9, as the gas
// cools), short enough for the two codes to stay on the same trajectories (see top).
TEST_P(CollisionCount, StatisticsAndSummaryMatchBruteForce) {
  const CountCase c = GetParam();
  const double end_time = 2.0;  // s
  Scene scene = parse_scene(scene_text(c.seed, c.restitution, end_time), "count.toml");
  build_initial_state(scene);

  // The scene gives what the oracle assumes: smooth, constant e, no TC model or low-speed
  // elasticity, no gravity, the six box walls.
  const System& system = scene.system;
  ASSERT_EQ(system.species.size(), std::size_t(kSpecies));
  ASSERT_EQ(system.walls.size(), std::size_t(kWalls));
  ASSERT_FALSE(system.flight.has_gravity());
  EXPECT_EQ(scene.method.event_driven.collapse.contact_time, 0.0);
  EXPECT_EQ(scene.method.event_driven.collapse.elastic_below_speed, 0.0);
  std::array<int, kWalls> carom_wall{};  // oracle wall -> carom wall index
  for (int w = 0; w < kWalls; ++w) {
    carom_wall[w] = -1;
    for (std::size_t k = 0; k < system.walls.size(); ++k)
      if (system.walls[k].name == kWallNames[w]) carom_wall[w] = static_cast<int>(k);
    ASSERT_GE(carom_wall[w], 0) << "no wall " << kWallNames[w];
  }
  for (int s = 0; s < kSpecies; ++s) {
    ASSERT_EQ(system.species[s].name, kSpeciesNames[s]);
    ASSERT_NEAR(system.species[s].mass(), kMass[s], 1e-14);
    for (int t = 0; t < kSpecies; ++t) {
      const ContactLaw& law = system.materials.pair(s, t);
      ASSERT_EQ(law.restitution, c.restitution);
      ASSERT_EQ(law.friction, 0.0);
    }
    for (int w = 0; w < kWalls; ++w) {
      const ContactLaw& law = system.materials.wall(s, carom_wall[w]);
      ASSERT_EQ(law.restitution, c.restitution);
      ASSERT_EQ(law.friction, 0.0);
    }
  }

  // The oracle starts from the scene's particles (listed: id k is entry k).
  const ParticleStore& start = system.particles;
  ASSERT_EQ(start.size(), std::size_t(kSpecies * kPerSpecies));
  std::vector<Ball> balls(start.size());
  std::array<std::size_t, kSpecies> count{};
  for (std::size_t i = 0; i < start.size(); ++i) {
    const int s = static_cast<int>(start.species[i]);
    balls[start.id[i]] =
        Ball{start.position[i], start.velocity[i], start.radius[i], start.mass[i], s};
    ++count[s];
  }
  BruteForceGas oracle(balls, system.domain.lower, system.domain.upper, c.restitution);
  oracle.run_until(end_time);

  EventDrivenOptions options = scene.method.event_driven;
  options.check_invariants = true;  // no overlap, momentum balance at every collision
  EventDrivenEngine sim(scene.system, options);
  const RunAnalysis analysis(scene, sim);
  ASSERT_TRUE(sim.run_until(end_time));
  ASSERT_EQ(sim.time(), end_time);

  // Same trajectories: final positions agree to 1e-9 of the box.
  double worst = 0.0, worst_velocity = 0.0;
  const ParticleStore& p = sim.system().particles;
  for (std::size_t i = 0; i < sim.particle_count(); ++i) {
    const Ball& b = oracle.balls()[p.id[i]];
    worst = std::max(worst, (sim.position(i) - b.position).norm() / kBox);
    worst_velocity = std::max(worst_velocity, (sim.velocity(i) - b.velocity).norm());
  }

  const Counts& expected = oracle.counts();
  const RunStatistics& st = sim.statistics();
  std::printf(
      "e = %.2f seed %llu: %llu pair + %llu wall collisions (ll %llu, ls %llu, ss %llu; "
      "large@walls %llu, small@walls %llu); final positions agree to %.1e of the box, "
      "velocities to %.1e m/s\n",
      c.restitution, static_cast<unsigned long long>(c.seed),
      static_cast<unsigned long long>(expected.pair_events),
      static_cast<unsigned long long>(expected.wall_events),
      static_cast<unsigned long long>(expected.pair[0][0]),
      static_cast<unsigned long long>(expected.pair[0][1]),
      static_cast<unsigned long long>(expected.pair[1][1]),
      static_cast<unsigned long long>(expected.walls(0)),
      static_cast<unsigned long long>(expected.walls(1)), worst, worst_velocity);
  ASSERT_LT(worst, 1e-9) << "the two codes left each other's trajectories: the counts below would "
                            "differ for chaotic, not bookkeeping, reasons (shorten the run)";

  // The run is a real check: every species pair collides, both species hit the walls, and
  // there are a few pair collisions per particle (2 per pair event).
  for (int s = 0; s < kSpecies; ++s)
    for (int t = 0; t < kSpecies; ++t) EXPECT_GE(expected.pair[s][t], 5u) << s << "-" << t;
  for (int s = 0; s < kSpecies; ++s)
    EXPECT_GE(expected.walls(s), 20u) << kSpeciesNames[s] << " with walls";
  const double per_particle =
      2.0 * static_cast<double>(expected.pair_events) / double(start.size());
  EXPECT_GE(per_particle, 3.0);
  EXPECT_LE(per_particle, 12.0);

  // RunStatistics, exactly.
  EXPECT_EQ(st.pair_events, expected.pair_events);
  EXPECT_EQ(st.wall_events, expected.wall_events);
  EXPECT_EQ(st.collisions(), expected.pair_events + expected.wall_events);
  ASSERT_EQ(st.species_count, std::size_t(kSpecies));
  ASSERT_EQ(st.wall_count, std::size_t(kWalls));
  for (int s = 0; s < kSpecies; ++s) {
    for (int t = 0; t < kSpecies; ++t)
      EXPECT_EQ(st.pair(s, t), expected.pair[s][t]) << kSpeciesNames[s] << "-" << kSpeciesNames[t];
    for (int w = 0; w < kWalls; ++w)
      EXPECT_EQ(st.wall(s, carom_wall[w]), expected.wall[s][w])
          << kSpeciesNames[s] << "@" << kWallNames[w];
  }
  // The impacts, exactly; a real check only when some collisions are slower than the impact
  // speed and some faster.
  std::uint64_t impacts = 0;
  for (int s = 0; s < kSpecies; ++s) {
    for (int t = 0; t < kSpecies; ++t) {
      EXPECT_EQ(st.pair_impact(s, t), expected.pair_impacts[s][t])
          << kSpeciesNames[s] << "-" << kSpeciesNames[t] << " impacts";
      impacts += expected.pair_impacts[s][t];
    }
    for (int w = 0; w < kWalls; ++w)
      EXPECT_EQ(st.wall_impact(s, carom_wall[w]), expected.wall_impacts[s][w])
          << kSpeciesNames[s] << "@" << kWallNames[w] << " impacts";
  }
  EXPECT_GT(impacts, 0u);
  std::uint64_t pairs = 0;
  for (int s = 0; s < kSpecies; ++s)
    for (int t = 0; t < kSpecies; ++t) pairs += expected.pair[s][t];
  EXPECT_LT(impacts, pairs);

  // The analysis layer: summary.json's collision_frequency per particle, nu_st = C_st (2 if
  // s = t, as both particles of a like collision count) / (N_s T), and s@walls = C_s,walls /
  // (N_s T). Tolerance 1e-12 relative: the same integer counts, converted with a different
  // order of the floating-point operations (a few ulps); one collision more or less is 2 % or more.
  const nlohmann::json summary = nlohmann::json::parse(analysis.summary_json(sim));
  const nlohmann::json& frequency = summary.at("collision_frequency");
  for (int s = 0; s < kSpecies; ++s) {
    const double per = 1.0 / (static_cast<double>(count[s]) * end_time);
    for (int t = 0; t < kSpecies; ++t) {
      const std::string key = kSpeciesNames[s] + "-" + kSpeciesNames[t];
      const double want = static_cast<double>(expected.pair[s][t]) * (s == t ? 2.0 : 1.0) * per;
      ASSERT_TRUE(frequency.contains(key)) << key;
      EXPECT_NEAR(frequency.at(key).get<double>(), want, 1e-12 * want) << key;
    }
    const std::string key = kSpeciesNames[s] + "@walls";
    const double want = static_cast<double>(expected.walls(s)) * per;
    ASSERT_TRUE(frequency.contains(key)) << key;
    EXPECT_NEAR(frequency.at(key).get<double>(), want, 1e-12 * want) << key;
  }
  // The same for the impacts (impact_frequency), and the speed they were counted at.
  EXPECT_EQ(summary.at("impact_speed").get<double>(), kImpactSpeed);
  const nlohmann::json& impact = summary.at("impact_frequency");
  for (int s = 0; s < kSpecies; ++s) {
    const double per = 1.0 / (static_cast<double>(count[s]) * end_time);
    for (int t = 0; t < kSpecies; ++t) {
      const std::string key = kSpeciesNames[s] + "-" + kSpeciesNames[t];
      const double want =
          static_cast<double>(expected.pair_impacts[s][t]) * (s == t ? 2.0 : 1.0) * per;
      EXPECT_NEAR(impact.at(key).get<double>(), want, 1e-12 * want) << key << " impacts";
    }
    std::uint64_t walls = 0;
    for (int w = 0; w < kWalls; ++w) walls += expected.wall_impacts[s][w];
    const double want = static_cast<double>(walls) * per;
    EXPECT_NEAR(impact.at(kSpeciesNames[s] + "@walls").get<double>(), want, 1e-12 * want);
  }
}

std::string case_name(const ::testing::TestParamInfo<CountCase>& info) {
  return (info.param.restitution == 1.0 ? std::string("Elastic") : std::string("E09")) + "Seed" +
         std::to_string(info.param.seed);
}

// Five random initial states, elastic and inelastic (e = 0.9, no TC model: too few collisions
// in 2 s for inelastic collapse).
INSTANTIATE_TEST_SUITE_P(BruteForce, CollisionCount,
                         ::testing::Values(CountCase{1.0, 1}, CountCase{1.0, 2}, CountCase{1.0, 3},
                                           CountCase{1.0, 4}, CountCase{1.0, 5}, CountCase{0.9, 1},
                                           CountCase{0.9, 2}, CountCase{0.9, 3}, CountCase{0.9, 4},
                                           CountCase{0.9, 5}),
                         case_name);

}  // namespace
}  // namespace carom
