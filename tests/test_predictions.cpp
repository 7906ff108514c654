// EventDrivenEngine predictions (events/event_driven/*_predictions.cpp) against brute-force integration of the trajectories.
//
// Small systems (2-4 particles, box walls, an inclined plane, a Wall::cylinder, two Wall::cones,
// gravity, periodic boxes, sizes 1:5) are built; the simulator processes its cell crossings until
// its earliest predicted event is a collision (EventDrivenEngine::predicted_events()). The oracle
// integrates every trajectory exactly from the initial state and finds, for every pair and
// particle-wall couple, the first time its gap falls below -tol by conservative advancement: it
// steps by (gap + tol) / L, where L bounds |d gap / dt| on the horizon, so it can never step
// over a contact. Tolerance tol = 1e-10 of the contact distance: the overlap the engine promises
// never to exceed (core/DESIGN.md, "Events and the calendar"); predicted times carry round-off
// ~1e-15, i.e. gaps ~1e-14.
//   No missed event: the engine's first collision is no later than the first overlap.
//   No spurious event: the gap of the engine's collision partner is zero (|gap| <= 1e-9 contact)
//   at the predicted time, and approaching.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <variant>

#include "core/rng.hpp"
#include "core/roots.hpp"
#include "events/event_driven/pair_batch.hpp"
#include "events/event_driven/engine.hpp"
#include "scenarios/scene/granular_gas.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

struct Scenario {
  std::string name;
  Domain domain;
  std::vector<Wall> extra_walls;
  Vec3 gravity = Vec3::Zero();
  std::vector<double> diameters;  // species diameters; particles draw from them
  int particles = 2;
  double horizon = 2.0;
};

// Initial states read back from the simulator (it reorders particles internally).
struct Oracle {
  Oracle(const EventDrivenEngine& simulator, double horizon_s) : sim(simulator), horizon(horizon_s) {
    for (std::size_t i = 0; i < sim.particle_count(); ++i) {
      r0.push_back(sim.position(i));
      v0.push_back(sim.velocity(i));
    }
  }
  const EventDrivenEngine& sim;
  double horizon;
  std::vector<Vec3> r0, v0;  // states at t = 0
  Vec3 r(std::size_t i, double s) const { return sim.system().flight.position(r0[i], v0[i], s); }
  double pair_gap(std::size_t i, std::size_t j, double s) const {
    const Domain& d = sim.system().domain;
    Vec3 dr0 = r(i, s) - r(j, s);
    for (int k = 0; k < 3; ++k)  // nearest image first (the separation grows without bound)
      if (d.periodic[k]) dr0[k] -= d.length()[k] * std::round(dr0[k] / d.length()[k]);
    double best = kNever;
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z) {
          const int shift[3] = {x, y, z};
          Vec3 dr = dr0;
          bool skip = false;
          for (int k = 0; k < 3; ++k) {
            if (shift[k] != 0 && !d.periodic[k]) skip = true;
            dr[k] += shift[k] * d.length()[k];
          }
          if (!skip) best = std::min(best, dr.norm());
        }
    const auto& a = sim.system().particles.radius;
    return best - (a[i] + a[j]);
  }
  double wall_gap(std::size_t i, std::size_t w, double s) const {
    return sim.system().walls[w].gap(r(i, s), sim.system().particles.radius[i]);
  }
  double pair_rate_bound(std::size_t i, std::size_t j) const {
    return (v0[i] - v0[j]).norm();  // gravity cancels
  }
  // Bound on |d gap / ds| over the horizon, per shape.
  struct WallRateBound {
    const Vec3& v;
    const Vec3& g;
    double horizon;
    double operator()(const PlaneWall& plane) const {
      return std::abs(v.dot(plane.normal)) + std::abs(g.dot(plane.normal)) * horizon;
    }
    double operator()(const CylinderWall&) const { return std::hypot(v.x(), v.y()); }
    // gap = (R(z) - rho) cos(alpha) - a: |gap'| <= (|slope| |v_z(s)| + |v_h|) cos(alpha).
    double operator()(const ConeWall& cone) const {
      return (std::abs(cone.slope()) * (std::abs(v.z()) + std::abs(g.z()) * horizon) +
              std::hypot(v.x(), v.y())) /
             cone.secant();
    }
    // gap = distance to the plate - a, 1-Lipschitz in the centre: |gap'| <= |v(s)|.
    double operator()(const PolygonWall&) const { return v.norm() + g.norm() * horizon; }
    // The same for a mesh (the distance to a union of triangles is 1-Lipschitz too; outside a
    // solid, where the particles are).
    double operator()(const MeshWall&) const { return v.norm() + g.norm() * horizon; }
  };
  double wall_rate_bound(std::size_t i, std::size_t w) const {
    return std::visit(WallRateBound{v0[i], sim.system().flight.gravity, horizon},
                      sim.system().walls[w].shape);
  }
  // First time in [0, horizon] at which gap < -tol (kNever if none).
  double first_overlap(const std::function<double(double)>& gap, double rate, double tol) const {
    if (rate <= 0.0) return gap(0.0) < -tol ? 0.0 : kNever;
    double s = 0.0;
    for (long it = 0; it < 20000000; ++it) {
      const double margin = gap(s) + tol;
      if (margin <= 1e-3 * tol) return s;
      s += margin / rate;
      if (s > horizon) return kNever;
    }
    return s;
  }
};

System build(const Scenario& sc, Rng& rng) {
  System system;
  system.domain = sc.domain;
  for (std::size_t k = 0; k < sc.diameters.size(); ++k)
    system.species.push_back(Species{"s" + std::to_string(k), sc.diameters[k], 1000.0});
  system.walls = box_walls(sc.domain);
  for (const Wall& w : sc.extra_walls) system.walls.push_back(w);
  ContactLaw law{0.9, 0.2, 0.1};
  system.materials = MaterialTable(system.species.size(), system.walls.size(), law, law);
  system.flight.gravity = sc.gravity;
  const Vec3 length = sc.domain.length();
  std::vector<Vec3> placed;
  std::vector<double> radii;
  for (int p = 0; p < sc.particles; ++p) {
    const auto s = static_cast<std::uint32_t>(rng.below(sc.diameters.size()));
    const double a = 0.5 * sc.diameters[s];
    for (int attempt = 0;; ++attempt) {
      Vec3 r;
      for (int k = 0; k < 3; ++k) r[k] = sc.domain.lower[k] + rng.uniform() * length[k];
      bool ok = true;
      for (const Wall& w : system.walls) ok = ok && w.gap(r, a) > 0.01 * a;
      for (std::size_t q = 0; q < placed.size(); ++q) {
        Vec3 dr = r - placed[q];
        sc.domain.minimum_image(dr);
        ok = ok && dr.norm() > 1.01 * (a + radii[q]);
      }
      if (ok) {
        placed.push_back(r);
        radii.push_back(a);
        break;
      }
      if (attempt > 100000) throw std::runtime_error("cannot place particles");
    }
  }
  for (std::size_t p = 0; p < placed.size(); ++p) {
    // Aim most particles at another one, so that pair collisions are common.
    Vec3 v = rng.normal3();
    if (placed.size() > 1 && rng.uniform() < 0.7) {
      Vec3 dr = placed[(p + 1) % placed.size()] - placed[p];
      sc.domain.minimum_image(dr);
      v = 2.0 * dr.normalized() + 0.3 * rng.normal3();
    }
    system.add_particle(radii[p] == 0.5 * sc.diameters[0] ? 0 : 1, placed[p], v, rng.normal3());
  }
  return system;
}

std::string fmt(const Vec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.17g %.17g %.17g)", v.x(), v.y(), v.z());
  return buf;
}

struct Check {
  int collisions_found = 0, nothing = 0;
};

void check_first_event(const Scenario& sc, std::uint64_t seed, Check& tally) {
  Rng rng(seed);
  System system = build(sc, rng);
  EventDrivenOptions options;
  options.check_invariants = true;
  EventDrivenEngine sim(system, options);
  const Oracle oracle(sim, sc.horizon);
  const std::size_t n = sim.particle_count(), walls = sim.system().walls.size();
  const auto& radius = sim.system().particles.radius;

  // Brute force: first overlap of any pair or particle-wall couple.
  double first_overlap = kNever;
  std::string first_what = "none";
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const double tol = 1e-10 * (radius[i] + radius[j]);
      const double s = oracle.first_overlap([&](double t) { return oracle.pair_gap(i, j, t); },
                                            oracle.pair_rate_bound(i, j), tol);
      if (s < first_overlap) {
        first_overlap = s;
        first_what = "pair " + std::to_string(i) + "-" + std::to_string(j);
      }
    }
    for (std::size_t w = 0; w < walls; ++w) {
      const double tol = 1e-10 * radius[i];
      const double s = oracle.first_overlap([&](double t) { return oracle.wall_gap(i, w, t); },
                                            oracle.wall_rate_bound(i, w), tol);
      if (s < first_overlap) {
        first_overlap = s;
        first_what = "particle " + std::to_string(i) + " wall " + sim.system().walls[w].name;
      }
    }
  }

  // Engine: process cell crossings until the earliest predicted event is a collision.
  Event first;
  std::size_t owner = 0;
  for (int loop = 0; loop < 100000; ++loop) {
    first = Event{};
    const std::vector<Event> events = sim.predicted_events();
    for (std::size_t i = 0; i < n; ++i)
      if (events[i].time < first.time) {
        first = events[i];
        owner = i;
      }
    if (first.kind != EventKind::CellCrossing || first.time > sc.horizon) break;
    if (std::getenv("CAROM_TEST_VERBOSE"))
      std::fprintf(stderr, "  crossing t=%.17g particle %zu face %d pos %s vel %s cell %d %d %d\n", first.time, owner, first.partner,
                   fmt(sim.position(owner)).c_str(), fmt(sim.velocity(owner)).c_str(), sim.grid().cell_of(owner)[0],
                   sim.grid().cell_of(owner)[1], sim.grid().cell_of(owner)[2]);
    sim.run_until(first.time);
    ASSERT_EQ(sim.statistics().collisions(), 0u) << "a collision appeared behind a cell crossing";
  }
  if (first.kind == EventKind::CellCrossing) first.time = kNever;  // nothing within the horizon
  SCOPED_TRACE(::testing::Message() << sc.name << " seed " << seed << ": oracle first overlap " << first_overlap
                                    << " (" << first_what << "), engine first collision " << first.time);
  // No missed event.
  EXPECT_LE(first.time, first_overlap) << "the engine misses a contact";
  if (first.time <= sc.horizon) {
    ++tally.collisions_found;
    // No spurious event: the partner really touches at the predicted time, approaching.
    const std::size_t i = owner;
    const double t = first.time;
    if (first.kind == EventKind::Pair) {
      const std::size_t j = static_cast<std::size_t>(first.partner);
      const double contact = radius[i] + radius[j];
      EXPECT_NEAR(oracle.pair_gap(i, j, t), 0.0, 1e-9 * contact) << "spurious pair event";
      EXPECT_LE(oracle.pair_gap(i, j, t + 1e-6), oracle.pair_gap(i, j, t - 1e-6) + 1e-12);
    } else {
      const std::size_t w = static_cast<std::size_t>(first.partner);
      EXPECT_NEAR(oracle.wall_gap(i, w, t), 0.0, 1e-9 * radius[i]) << "spurious wall event";
      EXPECT_LE(oracle.wall_gap(i, w, t + 1e-6), oracle.wall_gap(i, w, t - 1e-6) + 1e-12);
    }
  } else {
    ++tally.nothing;
  }
}

Domain box(const Vec3& lower, const Vec3& upper, std::array<bool, 3> periodic = {false, false, false}) {
  Domain d;
  d.lower = lower;
  d.upper = upper;
  d.periodic = periodic;
  return d;
}

void run_family_unguarded(const Scenario& sc, int trials, std::uint64_t seed0) {
  Check tally;
  for (int t = 0; t < trials; ++t) {
    if (std::getenv("CAROM_TEST_VERBOSE")) std::fprintf(stderr, "%s seed %llu\n", sc.name.c_str(), (unsigned long long)(seed0 + t));
    check_first_event(sc, seed0 + t, tally);
    if (::testing::Test::HasFatalFailure()) return;
  }
  // The family must exercise collisions, not only empty flights.
  EXPECT_GT(tally.collisions_found, trials / 2) << sc.name;
}

// The family runs in a child process with a 20 s watchdog, so an event loop that never
// reaches its end time is reported as a failure instead of hanging the suite.
void run_family(const Scenario& sc, int trials, std::uint64_t seed0) {
  test::expect_finishes(20, [&] { run_family_unguarded(sc, trials, seed0); });
}

TEST(Predictions, TwoParticlesInWalledBox) {
  run_family({"walled box", box(Vec3::Zero(), Vec3::Constant(6.0)), {}, Vec3::Zero(), {1.0}, 2, 3.0}, 300, 100);
}

TEST(Predictions, FourParticlesWithGravity) {
  run_family({"gravity", box(Vec3::Zero(), Vec3(5, 4, 6)), {}, Vec3(0, 0, -9.81), {1.0, 0.6}, 4, 2.0}, 300, 1000);
}

TEST(Predictions, TiltedGravityAndInclinedPlane) {
  Scenario sc{"inclined plane", box(Vec3::Zero(), Vec3(6, 6, 6)),
              {Wall::plane("incline", Vec3(0, 0, 1.5), Vec3(0.4, -0.3, 1.0))}, Vec3(1.5, -2.0, -9.0), {1.0}, 3, 2.0};
  run_family(sc, 300, 2000);
}

TEST(Predictions, CylinderWithGravity) {
  Scenario sc{"cylinder", box(Vec3(-3, -3, 0), Vec3(3, 3, 6)), {Wall::cylinder("pipe", 0.2, -0.1, 2.6)},
              Vec3(0, 0, -9.81), {1.0, 0.5}, 3, 2.0};
  run_family(sc, 300, 3000);
}

// A hopper (the cone widens upwards; apex at z = -4.2, below the box) and a converging duct
// (narrowing upwards; apex at z = 9.2, above it), both with gravity along the axis: the
// quartic contact condition, its roots on the other nappe rejected.
TEST(Predictions, ConeHopperWithGravity) {
  Scenario sc{"cone hopper", box(Vec3(-3, -3, 0), Vec3(3, 3, 6)),
              {Wall::cone("hopper", 0.2, -0.1, 0.0, 1.2, 6.0, 2.9)}, Vec3(0, 0, -9.81), {1.0, 0.5}, 3, 2.0};
  run_family(sc, 300, 6000);
}

TEST(Predictions, ConeNarrowingUpwardsWithGravity) {
  Scenario sc{"cone duct", box(Vec3(-3, -3, 0), Vec3(3, 3, 6)),
              {Wall::cone("duct", -0.1, 0.3, 0.0, 2.9, 6.0, 1.0)}, Vec3(0, 0, -9.81), {1.0, 0.5}, 3, 2.0};
  run_family(sc, 300, 7000);
}

TEST(Predictions, PeriodicBox) {
  Scenario sc{"periodic", box(Vec3::Zero(), Vec3(4.6, 5.3, 7.0), {true, true, true}), {}, Vec3::Zero(), {1.0}, 3, 6.0};
  run_family(sc, 300, 4000);
}

TEST(Predictions, SizeRatioOneToFiveMixedBoundaries) {
  Scenario sc{"1:5 mixed", box(Vec3::Zero(), Vec3(5.2, 5.5, 4.5), {true, false, false}), {},
              Vec3(0, 0, -3.0), {1.0, 0.2}, 4, 2.0};
  run_family(sc, 300, 5000);
}

// A periodic axis only three cells long is refused: there the two end cells are neighbours both
// directly and through the boundary, and the nearest image at the time of a prediction is not
// always the image that touches (cells 1.1 wide: A at x = 0.95 and B at x = 2.35 are 1.4 apart
// directly and 1.9 through the boundary; moving apart directly they touch through the boundary).
TEST(Predictions, PeriodicAxisOfThreeCellsIsRefused) {
  System system;
  system.domain = box(Vec3::Zero(), Vec3(3.3, 3.3, 3.3), {true, true, true});
  system.species.push_back(Species{"s", 1.0, 1000.0});
  system.materials = MaterialTable(1, 0, ContactLaw{}, ContactLaw{});
  system.add_particle(0, Vec3(0.95, 1.65, 1.65), Vec3(-1, 0, 0));
  try {
    EventDrivenEngine sim(system);
    ADD_FAILURE() << "a periodic axis of three cells was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at least 4 particle diameters"), std::string::npos) << e.what();
  }
}

// The same approach through the boundary with four cells 1.1 wide: A at x = 0.95 (cell 0) and
// B at x = 3.45 (cell 3) are 2.5 apart directly and 1.9 through the boundary; moving apart
// directly at 1 m/s each, they touch through the boundary when 1.9 - 2 t = 1, at t = 0.45.
TEST(Predictions, PeriodicAxisOfFourCells) {
  System system;
  system.domain = box(Vec3::Zero(), Vec3(4.4, 4.4, 4.4), {true, true, true});
  system.species.push_back(Species{"s", 1.0, 1000.0});
  system.materials = MaterialTable(1, 0, ContactLaw{}, ContactLaw{});
  system.add_particle(0, Vec3(0.95, 2.2, 2.2), Vec3(-1, 0, 0));
  system.add_particle(0, Vec3(3.45, 2.2, 2.2), Vec3(1, 0, 0));
  EventDrivenEngine sim(system);
  sim.run_until(0.44);
  EXPECT_EQ(sim.statistics().pair_events, 0u);
  sim.run_until(0.46);
  EXPECT_EQ(sim.statistics().pair_events, 1u) << "the contact through the periodic boundary at t = 0.45 was missed";
  // Random systems in boxes of 4.0 to 4.9 diameters (four cells per axis).
  Scenario sc{"periodic 4 cells", box(Vec3::Zero(), Vec3(4.1, 4.5, 4.9), {true, true, true}), {}, Vec3::Zero(), {1.0}, 2, 6.0};
  run_family(sc, 200, 6000);
}

}  // namespace
}  // namespace carom

namespace carom {
namespace {

// A particle falling back through a horizontal cell face after rising from where it was last
// stored. Box 4 x 4 x 4 with walls, d = 1 (cells 1 wide), g = -9.81 z. Start at z = 2.6 (cell 2)
// moving up at 0.5 m/s: it peaks at z = 2.613, falls through the face z = 2 at t = 0.404 and
// lands on the floor (centre at z = 0.5) at t = 0.7025 (exactly: 2.6 + 0.5 t - 4.905 t^2 = 0.5).
// Reference: the closed-form flight; tolerance 1e-9 s on the landing time (the engine solves
// the same quadratic; round-off ~1e-15). Must finish within 5 s (it is a handful of events).
TEST(Predictions, FallingBackThroughACellFaceUnderGravity) {
  test::expect_finishes(5, [] {
                System system;
                system.domain.upper = Vec3(4, 4, 4);
                system.species.push_back(Species{"s", 1.0, 1000.0});
                system.walls = box_walls(system.domain);
                system.materials = MaterialTable(1, system.walls.size(), ContactLaw{}, ContactLaw{});
                system.flight.gravity = Vec3(0, 0, -9.81);
                system.add_particle(0, Vec3(2, 2, 2.6), Vec3(0, 0, 0.5));
                EventDrivenEngine sim(system);
                const double landing = (0.5 + std::sqrt(0.25 + 4 * 4.905 * 2.1)) / 9.81;
                sim.run_until(landing - 1e-6);
                EXPECT_EQ(sim.statistics().wall_events, 0u);
                EXPECT_EQ(sim.statistics().cell_crossings, 2u) << "down through z = 2 and z = 1, once each";
                sim.run_until(landing + 1e-6);
                EXPECT_EQ(sim.statistics().wall_events, 1u);
              });
}

// Without gravity the engine predicts cell crossings with a branch-free formula
// (EventDrivenEngine::straight_cell_crossing). Oracle: the general form, first_upward_crossing on both
// faces of every axis in order (the path that flights under gravity take), which must give the
// same face and the same time bit for bit, for every particle of a gas in a box with two walled
// and one periodic axis (so outer faces, which no crossing may name, are exercised), at the
// start and again after 2000 collisions (clocks then differ from particle to particle).
TEST(Predictions, StraightCellCrossingsAreTheGeneralRootsBitForBit) {
  Scenario sc;
  sc.name = "crossings";
  sc.domain = box(Vec3(0, 0, 0), Vec3(8, 9, 10), {false, true, false});
  sc.diameters = {1.0};
  sc.particles = 150;
  Rng rng(2024);
  EventDrivenEngine sim(build(sc, rng));
  auto oracle = [&](std::size_t i, const Vec3& r, const Vec3& v, double clock) {
    const HierarchicalGrid& grid = sim.grid();
    const auto p = static_cast<std::int32_t>(i);
    const Vec3 lower = grid.cell_lower(p), upper = grid.cell_upper(p);
    Event best;
    for (int k = 0; k < 3; ++k) {
      if (!grid.is_outer_face(p, k, +1)) {
        const double t = clock + first_upward_crossing(0.0, v[k], r[k] - upper[k]);
        if (t < best.time) best = Event{t, 2 * k + 1, 0, EventKind::CellCrossing};
      }
      if (!grid.is_outer_face(p, k, -1)) {
        const double t = clock + first_upward_crossing(0.0, -v[k], lower[k] - r[k]);
        if (t < best.time) best = Event{t, 2 * k, 0, EventKind::CellCrossing};
      }
    }
    return best;
  };
  int outer_faces_nearby = 0;
  for (int stage = 0; stage < 2; ++stage) {
    if (stage == 1) test::run_collisions(sim, 2000, 0.05);
    const EngineState state = sim.state();
    for (std::size_t i = 0; i < sim.particle_count(); ++i) {
      const ParticleStore& p = state.particles;
      const Event expected = oracle(i, p.position[i], p.velocity[i], p.clock[i]);
      const Event& crossing = state.crossings[i];
      ASSERT_EQ(crossing.kind, expected.kind) << "particle " << i;
      ASSERT_EQ(crossing.partner, expected.partner) << "particle " << i;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(crossing.time),
                std::bit_cast<std::uint64_t>(expected.time))
          << "particle " << i << ": " << crossing.time << " against " << expected.time;
      for (int k : {0, 2})
        outer_faces_nearby += sim.grid().is_outer_face(static_cast<std::int32_t>(i), k, +1) ||
                              sim.grid().is_outer_face(static_cast<std::int32_t>(i), k, -1);
    }
  }
  EXPECT_GT(outer_faces_nearby, 50) << "the walled axes' outer cells must be exercised";
}

// The cell scan (EventDrivenEngine::scan_cells: cell lists walked two particles at a time, candidates
// tested four at a time in batches) against brute force. In a dense fluid (phi = 0.40, melted
// from its lattice for 20 collisions per particle, so that cells hold 0 to 3 particles), every
// particle's predicted collision must be, bit for bit and with the same partner, the earliest
// pair_contact (the scalar reference) over all particles whose cells are within one cell of its
// own on every axis, found by checking all N of them. A fresh simulator is built from the
// melted state at one time, so that every prediction is made from the same states.
TEST(Predictions, DenseGasCollisionsAreTheEarliestOfTheCellBlockByBruteForce) {
  GranularGasSpec spec;
  spec.count = 2000;
  spec.volume_fraction = 0.40;
  spec.seed = 7;
  EventDrivenEngine melt(make_granular_gas(spec));
  test::run_collisions(melt, 20 * 2000 / 2, 0.05);
  System system = melt.system();
  for (std::size_t i = 0; i < melt.particle_count(); ++i) {
    system.particles.position[i] = melt.position(i);
    system.particles.velocity[i] = melt.velocity(i);
    system.particles.clock[i] = melt.time();
  }
  const EventDrivenEngine sim(system);
  const EngineState state = sim.state();
  const ParticleStore& p = state.particles;
  const HierarchicalGrid& grid = sim.grid();
  ASSERT_EQ(grid.levels().size(), 1u);
  const auto& cells = grid.levels()[0].cells;
  auto near = [&](std::size_t i, std::size_t j) {
    for (int k = 0; k < 3; ++k) {
      const int n = cells[k];
      const int d = ((grid.cell_of(int(j))[k] - grid.cell_of(int(i))[k]) % n + n) % n;
      if (d != 0 && d != 1 && d != n - 1) return false;
    }
    return true;
  };
  int shared_cells = 0;
  for (std::size_t i = 0; i < sim.particle_count(); ++i) {
    double best = kNever;
    int partner = -1;
    for (std::size_t j = 0; j < sim.particle_count(); ++j) {
      if (j == i || !near(i, j)) continue;
      shared_cells += grid.cell_of(int(j)) == grid.cell_of(int(i));
      const double t = pair_contact<false, true>(
          p.position[i], p.velocity[i], p.clock[i], p.radius[i], p.position[j], p.velocity[j],
          p.clock[j], p.radius[j], Vec3::Zero(), system.domain);
      if (t < best) {
        best = t;
        partner = int(j);
      }
    }
    const Event& predicted = state.events[i];
    ASSERT_EQ(predicted.partner, partner) << "particle " << i;
    ASSERT_EQ(std::bit_cast<std::uint64_t>(predicted.time), std::bit_cast<std::uint64_t>(best))
        << "particle " << i << ": " << predicted.time << " against " << best;
  }
  EXPECT_GT(shared_cells, 500) << "cells holding two or more particles must be exercised";
}

}  // namespace
}  // namespace carom
