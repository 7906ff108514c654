// Polygon walls in runs of the three methods: a sphere bouncing off an inclined square plate
// (event-driven: the first bounce in closed form, energy books, never inside the plate), a
// sphere passing beside the plate's edge (not deflected) or clipping it (deflected outward),
// and a ball bouncing on a horizontal plate with the soft-sphere and Monte Carlo methods
// (rebound height e^2 h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/system.hpp"
#include "events/event_driven/engine.hpp"
#include "events/monte_carlo/engine.hpp"
#include "events/soft_sphere/engine.hpp"
#include "test_support.hpp"

namespace carom {
namespace {

constexpr double kG = 9.81;
constexpr double kA = 2e-3;  // sphere radius, m

/// A box 0.2 x 0.2 x 0.25 m (walled), gravity -z, glass beads of 4 mm, and a square plate of
/// side 0.1 m centred at (0, 0, 0.08) tilted by `tilt` (rad) about x.
System plate_box(double tilt, const ContactLaw& law) {
  System s;
  s.domain.lower = Vec3(-0.1, -0.1, 0.0);
  s.domain.upper = Vec3(0.1, 0.1, 0.25);
  s.flight.gravity = Vec3(0, 0, -kG);
  s.species.push_back(Species{"bead", 2.0 * kA, 2500.0});
  s.walls = box_walls(s.domain);
  const Vec3 c(0, 0, 0.08), ex(0.05, 0, 0), ey = 0.05 * Vec3(0, std::cos(tilt), std::sin(tilt));
  s.walls.push_back(Wall::polygon("plate", {c - ex - ey, c + ex - ey, c + ex + ey, c - ex + ey}));
  s.materials = MaterialTable(1, s.walls.size(), law, law);
  return s;
}

// Dropped from rest at (0, 0, z0) onto the plate tilted by 30 degrees (smooth, e = 0.8): it
// touches where the centre is a above the plane, z* = 0.08 + a / cos 30, at t* =
// sqrt(2 (z0 - z*) / g), and leaves with v - (1 + e) (v.n) n. Compared just after, 1e-12 of
// the speed (round-off: the engine computes the same numbers by other steps).
TEST(PolygonEventDriven, BounceOffAnInclinedPlateInClosedForm) {
  const double tilt = 3.14159265358979323846 / 6.0, e = 0.8, z0 = 0.15;
  System s = plate_box(tilt, ContactLaw{e, 0.0, -1.0, -1.0});
  s.add_particle(0, Vec3(0, 0, z0), Vec3::Zero());
  EventDrivenOptions options;
  options.check_invariants = true;
  EventDrivenEngine sim(s, options);
  const double z_star = 0.08 + kA / std::cos(tilt), t_star = std::sqrt(2 * (z0 - z_star) / kG);
  const Vec3 n(0, -std::sin(tilt), std::cos(tilt));
  const Vec3 v_in(0, 0, -kG * t_star);
  const Vec3 v_out = v_in - (1 + e) * v_in.dot(n) * n;
  const double later = 1e-4;
  sim.run_until(t_star + later);
  const std::size_t plate = sim.system().walls.size() - 1;
  EXPECT_EQ(sim.statistics().wall(0, plate), 1u);
  EXPECT_LE((sim.velocity(0) - (v_out + later * sim.system().flight.gravity)).norm(),
            1e-12 * v_in.norm());
  const Vec3 r_out =
      Vec3(0, 0, z_star) + later * v_out + 0.5 * later * later * sim.system().flight.gravity;
  EXPECT_LE((sim.position(0) - r_out).norm(), 1e-12);
}

/// Which side of the plate a centre r is on (+1 or -1) where its foot lies more than `margin`
/// inside the polygon, 0 elsewhere.
int side_over_the_face(const PolygonWall& plate, const Vec3& r, double margin) {
  const std::vector<Vec3>& p = plate.vertices();
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec3 outward = (p[(k + 1) % p.size()] - p[k]).cross(plate.normal()).normalized();
    if ((r - p[k]).dot(outward) > -margin) return 0;
  }
  return (r - plate.centre()).dot(plate.normal()) > 0.0 ? 1 : -1;
}

// 30 beads dropped from random places over the tilted plate (17 degrees; rough, inelastic, TC
// model) run 1 s: they hop down the plate, fall off its edges and corners, bounce on the floor
// and some come back up under the plate. References: never inside the plate (the engine's
// invariant checks at every wall collision, 1e-10 of the radius, and every particle's gap
// at 1000 times); never through it (at every ms, a bead whose foot is more than 6 mm inside
// the polygon must be on the side it was on at the previous such sample: it moves less than
// 2.5 mm per ms, so it cannot have gone round the rim in between); the energy books close to
// 1e-11 of the initial total (as the cone's hopper: round-off of a few ulps per collision; a
// missed contact or a wrong normal shows as a jump). Every bead lands on the plate: more than
// 30 plate collisions.
TEST(PolygonEventDriven, BeadsOnAnInclinedPlateStayOutAndCloseTheEnergy) {
  test::expect_finishes(60, [] {
    ContactLaw law{0.8, 0.3, 0.2, -1.0};
    System s = plate_box(0.3, law);
    Rng rng(81);
    while (s.particles.size() < 30) {
      const Vec3 r(rng.uniform(-0.035, 0.035), rng.uniform(-0.035, 0.035), rng.uniform(0.14, 0.24));
      bool clear = true;
      for (std::size_t j = 0; j < s.particles.size(); ++j)
        clear = clear && (s.particles.position[j] - r).norm() > 2.2 * kA;
      if (clear) s.add_particle(0, r, 0.02 * rng.normal3());
    }
    EventDrivenOptions options;
    options.check_invariants = true;
    options.collapse.contact_time = 1e-5;
    EventDrivenEngine sim(s, options);
    const PolygonWall& shape = std::get<PolygonWall>(sim.system().walls.back().shape);
    const double total0 = sim.energies().total();
    const std::size_t plate = sim.system().walls.size() - 1;
    double worst_energy = 0.0, worst_gap = 0.0, fastest = 0.0;
    std::vector<int> side(sim.particle_count(), 0);
    int crossings = 0, over = 0;
    for (int sample = 1; sample <= 1000; ++sample) {
      sim.run_until(1e-3 * sample);
      worst_energy =
          std::max(worst_energy, std::abs(sim.energies().total() - total0) / std::abs(total0));
      worst_gap = std::max(worst_gap, test::max_relative_wall_overlap(sim));
      for (std::size_t i = 0; i < sim.particle_count(); ++i) {
        fastest = std::max(fastest, sim.velocity(i).norm());
        const int here = side_over_the_face(shape, sim.position(i), 6e-3);
        if (here != 0 && side[i] != 0 && here != side[i]) ++crossings;
        if (here != 0) ++over;
        side[i] = here;
      }
    }
    std::printf(
        "[ plate ] %llu collisions (%llu with the plate), worst wall overlap %.2g of a "
        "radius, worst energy closure %.2g, fastest %.2f m/s\n",
        (unsigned long long)sim.statistics().collisions(),
        (unsigned long long)sim.statistics().wall(0, plate), worst_gap, worst_energy, fastest);
    EXPECT_LE(worst_gap, 1e-10);
    EXPECT_LT(worst_energy, 1e-11);
    EXPECT_LT(fastest, 2.5) << "the crossing check needs less than 2.5 mm per sample";
    EXPECT_EQ(crossings, 0) << "a bead went through the plate";
    EXPECT_GT(over, 1000) << "bead-samples over the face";
    EXPECT_GT(sim.statistics().wall(0, plate), 30u);
  });
}

// Beside the plate's edge (x = 0.05): a bead falling at x = 0.05 + a + 1e-5 passes it and falls
// freely to the floor (position against the free fall to 1e-12 m, no plate collision); at
// x = 0.05 + a - 1e-4 it clips the edge and is pushed outward (+x), with the edge's normal
// (x - 0.05, 0, z - 0.08) / a at the impact, not the face's.
TEST(PolygonEventDriven, BesideTheEdgeNotDeflectedOnItDeflectedOutward) {
  const ContactLaw law{0.8, 0.0, -1.0, -1.0};
  for (const double offset : {1e-5, -1e-4}) {
    System s = plate_box(0.0, law);
    const double x = 0.05 + kA + offset, z0 = 0.15;
    s.add_particle(0, Vec3(x, 0.01, z0), Vec3::Zero());
    EventDrivenOptions options;
    options.check_invariants = true;
    EventDrivenEngine sim(s, options);
    const std::size_t plate = sim.system().walls.size() - 1;
    const double t = 0.16;  // before the floor (z = a at t = 0.173 s)
    sim.run_until(t);
    if (offset > 0) {
      EXPECT_EQ(sim.statistics().wall(0, plate), 0u);
      EXPECT_LE((sim.position(0) - Vec3(x, 0.01, z0 - 0.5 * kG * t * t)).norm(), 1e-12);
    } else {
      EXPECT_EQ(sim.statistics().wall(0, plate), 1u);
      // Contact with the edge line: (x - 0.05)^2 + (z - 0.08)^2 = a^2, above it.
      const double dz = std::sqrt(kA * kA - (x - 0.05) * (x - 0.05));
      const double t_star = std::sqrt(2 * (z0 - 0.08 - dz) / kG);
      const Vec3 n = Vec3(x - 0.05, 0, dz) / kA;
      const Vec3 v_in(0, 0, -kG * t_star);
      const Vec3 v_out = v_in - 1.8 * v_in.dot(n) * n;
      EXPECT_GT(v_out.x(), 0.0);
      EXPECT_LE((sim.velocity(0) - (v_out + Vec3(0, 0, -kG * (t - t_star)))).norm(),
                1e-12 * v_in.norm());
    }
  }
}

/// A horizontal plate of side 0.1 m at z = 0.05 (centred), one bead of radius a dropped from
/// rest with its lowest point h above the plate, smooth law with restitution e.
System ball_on_plate(double e, double h) {
  System s = plate_box(0.0, ContactLaw{e, 0.0, -1.0, -1.0});
  // Move the plate down to z = 0.05.
  std::vector<Vec3> square;
  for (const Vec3& p : std::get<PolygonWall>(s.walls.back().shape).vertices())
    square.push_back(p - Vec3(0, 0, 0.03));
  s.walls.back() = Wall::polygon("plate", square);
  s.add_particle(0, Vec3(0.01, -0.02, 0.05 + kA + h), Vec3::Zero());
  return s;
}

// Monte Carlo (no partners: one bead): the wall impact is an exact event inside the step, so
// the rebound's apex is e^2 h above contact to round-off (1e-12 m), and the height at times
// inside steps is the closed form.
TEST(PolygonMonteCarlo, BallReboundsToESquaredTheHeight) {
  const double e = 0.7, h = 0.03;
  MonteCarloOptions options;
  options.time_step = 0.01;
  MonteCarloEngine mc(ball_on_plate(e, h), options);
  const double impact = std::sqrt(2 * h / kG), rebound = e * kG * impact;
  const double apex = impact + rebound / kG;
  for (double t : {0.0501, impact + 1e-4, 0.1203, apex}) {
    mc.run_until(t);
    const double s = t - impact;
    const double z =
        s < 0 ? 0.05 + kA + h - 0.5 * kG * t * t : 0.05 + kA + rebound * s - 0.5 * kG * s * s;
    EXPECT_NEAR(mc.position(0).z(), z, 1e-12) << "t = " << t;
  }
  EXPECT_NEAR(mc.position(0).z() - 0.05 - kA, e * e * h, 1e-12);
  EXPECT_EQ(mc.statistics().wall(0, mc.system().walls.size() - 1), 1u);
}

// Soft spheres (Hertz, glass-like E = 1e8 Pa, damping for e at the impact speed, step
// t_c / 1000): the rebound apex is e^2 h above contact to 6e-3 relative (the restitution is
// right to 3e-3 at this step, SoftImpact.HertzReboundsWithTheSceneRestitutionAtEverySpeed, and
// the apex goes with its square; gravity during the 1e-5 s contact changes it by ~1e-4).
TEST(PolygonSoftSphere, BallReboundsToESquaredTheHeight) {
  for (const double e : {0.5, 0.9}) {
    const double h = 0.03;
    SoftSphereOptions o;
    o.model = ContactModel::HertzMindlin;
    o.species_materials = {ElasticMaterial{1e8, 0.3}};
    o.impact_speed = std::sqrt(2 * kG * h);
    o.step_fraction = 1e-3;
    o.max_overlap = 0.5;
    SoftSphereEngine sim(ball_on_plate(e, h), o);
    const double dt = sim.time_step();
    bool touched = false;
    double apex = 0.0;
    while (sim.time() < 0.3) {
      sim.run_until(sim.time() + dt);
      const double gap = sim.system().walls.back().gap(sim.position(0), kA);
      if (gap < 0) touched = true;
      if (touched && gap > 0 && sim.velocity(0).z() > 0) {
        apex = sim.position(0).z() + sim.velocity(0).squaredNorm() / (2 * kG) - 0.05 - kA;
        break;
      }
    }
    ASSERT_TRUE(touched);
    EXPECT_NEAR(apex / (e * e * h), 1.0, 6e-3) << "e = " << e;
  }
}

}  // namespace
}  // namespace carom
