// Mesh walls in runs: a flat square plate made of two triangles gives the same trajectory as
// the single square polygon, with the event-driven method (a bead bouncing across the shared
// diagonal, rough law) and with soft spheres (a bead sliding and rolling across it: no snag, one
// contact); the mesh is one wall, its counters under one name.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/system.hpp"
#include "events/event_driven/engine.hpp"
#include "events/soft_sphere/engine.hpp"

namespace carom {
namespace {

constexpr double kG = 9.81;
constexpr double kA = 2e-3;  // sphere radius, m

/// A walled box 0.2 x 0.2 x 0.25 m, gravity -z, 4 mm glass beads, and a horizontal square
/// plate of side 0.1 m at z = 0.05 centred on the axis: one polygon, or (`mesh`) a mesh of the
/// two triangles split along the diagonal from (-0.05, -0.05) to (0.05, 0.05).
System square_plate(bool mesh, const ContactLaw& law) {
  System s;
  s.domain.lower = Vec3(-0.1, -0.1, 0.0);
  s.domain.upper = Vec3(0.1, 0.1, 0.25);
  s.flight.gravity = Vec3(0, 0, -kG);
  s.species.push_back(Species{"bead", 2.0 * kA, 2500.0});
  s.walls = box_walls(s.domain);
  const Vec3 p00(-0.05, -0.05, 0.05), p10(0.05, -0.05, 0.05), p11(0.05, 0.05, 0.05),
      p01(-0.05, 0.05, 0.05);
  if (mesh)
    s.walls.push_back(Wall::mesh("plate", {{p00, p10, p11}, {p00, p11, p01}}, false));
  else
    s.walls.push_back(Wall::polygon("plate", {p00, p10, p11, p01}));
  s.materials = MaterialTable(1, s.walls.size(), law, law);
  return s;
}

// Event-driven: a bead thrown across the plate (rough, inelastic: e = 0.8, mu = 0.3, beta0 =
// 0.4) bounces 3 times on it, crossing the diagonal, then falls off its edge to the floor. The two
// plates give the same contact times up to round-off (the triangles' planes, centres and normals
// are computed from other vertex sets: differences of a few 1e-17 m), and a bounce passes a
// perturbation on without growing it much (one bead, a flat plate: no chaos), so the positions
// agree to 1e-12 m (1e-10 of the plate's size) and the counts exactly.
TEST(MeshEventDriven, TwoTrianglesBounceLikeTheSquare) {
  const ContactLaw law{0.8, 0.3, 0.4, -1.0};
  auto build = [&](bool mesh) {
    System s = square_plate(mesh, law);
    s.add_particle(0, Vec3(-0.04, -0.03, 0.12), Vec3(0.25, 0.2, 0.0));
    EventDrivenOptions options;
    options.check_invariants = true;
    return EventDrivenEngine(s, options);
  };
  EventDrivenEngine square = build(false), triangles = build(true);
  const std::size_t plate = square.system().walls.size() - 1;
  for (double t = 0.02; t <= 0.8; t += 0.02) {
    square.run_until(t);
    triangles.run_until(t);
    ASSERT_LE((square.position(0) - triangles.position(0)).norm(), 1e-12) << "t = " << t;
    ASSERT_LE((square.velocity(0) - triangles.velocity(0)).norm(), 1e-10) << "t = " << t;
  }
  std::printf("[ mesh ] %d bounces on the plate\n",
              static_cast<int>(square.statistics().wall(0, plate)));
  EXPECT_GE(square.statistics().wall(0, plate), 3u);
  EXPECT_EQ(square.statistics().wall(0, plate), triangles.statistics().wall(0, plate));
  EXPECT_EQ(triangles.system().walls[plate].name, "plate");
}

// Soft spheres (Hertz-Mindlin, E = 1e8 Pa, mu = 0.3): a bead set down on the plate with a
// horizontal velocity slides, then rolls, across the diagonal. With the mesh as one wall its
// distance and normal are the plane's across the diagonal and the tangential spring carries on,
// so the trajectory is the square's to round-off amplified over ~1e5 steps: 1e-9 m (each step
// is a smooth map of the state; no contact is made or broken). A mesh split into two walls
// would make two contacts on the diagonal (twice the normal force there: a bump).
TEST(MeshSoftSphere, SlidingAcrossTheDiagonalDoesNotSnag) {
  const ContactLaw law{0.5, 0.3, 0.0, -1.0};
  auto build = [&](bool mesh) {
    System s = square_plate(mesh, law);
    s.add_particle(0, Vec3(-0.03, -0.02, 0.05 + kA * (1.0 - 1e-4)), Vec3(0.3, 0.1, 0.0));
    SoftSphereOptions o;
    o.model = ContactModel::HertzMindlin;
    o.species_materials = {ElasticMaterial{1e8, 0.3}};
    o.impact_speed = 0.1;
    o.max_overlap = 0.5;
    return SoftSphereEngine(s, o);
  };
  SoftSphereEngine square = build(false), triangles = build(true);
  double crossed = 0.0;  // when the centre passes over the diagonal x = y
  for (double t = 0.01; t <= 0.15; t += 0.01) {
    square.run_until(t);
    triangles.run_until(t);
    const Vec3 r = triangles.position(0);
    if (crossed == 0.0 && r.x() > r.y()) crossed = t;
    ASSERT_LE((square.position(0) - r).norm(), 1e-9) << "t = " << t;
    ASSERT_LE((square.velocity(0) - triangles.velocity(0)).norm(), 1e-7) << "t = " << t;
  }
  EXPECT_GT(crossed, 0.0) << "the bead never crossed the diagonal";
  EXPECT_NEAR(triangles.position(0).z(), 0.05 + kA, 1e-5) << "left the plate";
}

}  // namespace
}  // namespace carom
