#pragma once
// The Chung & Ooi (2011) benchmark impacts run two ways: by carom's soft-sphere method (3-D,
// the motion in the x-z plane, spins about y) and by the independent planar reference
// (contact_oracle.hpp). Materials and their sources: test_chung_ooi.cpp.
#include <cmath>
#include <numbers>

#include "tests/soft_sphere/contact_oracle.hpp"
#include "tests/soft_sphere/soft_support.hpp"

namespace carom::soft_test {

/// A benchmark material: E (Pa), nu, rho (kg/m^3).
struct BenchMaterial {
  const char* name;
  double young, poisson, density;
  OracleMaterial elastic() const { return {young, poisson}; }
};

/// The rigid plane of the benchmark: the sphere's material 1e10 times stiffer (as in the
/// ChungOoi.Test2 and Test3 tests).
inline OracleMaterial rigid_plane(const BenchMaterial& m) {
  return {1e10 * m.young, m.poisson};
}

/// Mass of a sphere of radius a, kg.
inline double sphere_mass(double a, double density) {
  return 4.0 / 3.0 * std::numbers::pi * a * a * a * density;
}

/// Sphere 1's (and sphere 2's) velocity in the x-z plane and spin about y after an impact.
struct Planar {
  double vx1 = 0, vz1 = 0, w1 = 0, vx2 = 0, vz2 = 0, w2 = 0;
};

/// carom: a sphere (radius a, material m) hits the floor (the rigid plane) with velocity
/// (vt, 0, -vn) and spin (0, w, 0); steps of step_fraction of the Hertz contact time.
inline Planar carom_on_plane(const BenchMaterial& m, double a, double e, double mu, double vt,
                             double vn, double w, double step_fraction) {
  ContactLaw law;
  law.restitution = e;
  law.friction = mu;
  System s = empty_system(2 * a, m.density, law, 1);
  s.domain.lower = Vec3(-1e3 * a, -1e3 * a, -1e3 * a);
  s.domain.upper = -s.domain.lower;
  s.add_particle(0, Vec3(0, 0, a * (1 + 1e-6)), Vec3(vt, 0, -vn), Vec3(0, w, 0));
  SoftSphereOptions o = hertz_options(m.young, m.poisson, 0.0);
  o.wall_materials = {ElasticMaterial{1e10 * m.young, m.poisson}};
  o.impact_speed = vn;
  o.step_fraction = step_fraction;
  SoftSphereEngine sim(s, o);
  const ImpactResult r = run_impact(sim, 1e3 * a / vn);
  return {r.v1.x(), r.v1.z(), r.w1.y(), 0, 0, 0};
}

/// The reference for the same impact, `steps` steps per contact time.
inline Planar oracle_on_plane(const OracleContact& c, const BenchMaterial& m, double a, double vt,
                              double vn, double w, double steps, OracleImpact* impulses = nullptr) {
  Body2D b1{0, a, vt, -vn, w, a, sphere_mass(a, m.density)};
  Body2D plane;
  const OracleImpact i = oracle_impact(b1, plane, c, steps);
  if (impulses) *impulses = i;
  return {b1.vx, b1.vz, b1.spin, 0, 0, 0};
}

/// Two spheres of material m: sphere 1 (radius a1, density rho1) above sphere 2 (a2, rho2),
/// centres on the z axis, touching; velocities (vx, 0, vz) and spins (0, w, 0).
struct PairShot {
  double a1, rho1, a2, rho2;
  double vx1, vz1, w1, vx2, vz2, w2;
};

/// carom on the pair, steps of step_fraction of the Hertz contact time.
inline Planar carom_pair(const BenchMaterial& m, const PairShot& p, double e, double mu,
                         double step_fraction) {
  ContactLaw law;
  law.restitution = e;
  law.friction = mu;
  System s;
  const double size = 20 * (p.a1 + p.a2);
  s.domain.lower = Vec3(-size, -size, -size);
  s.domain.upper = Vec3(size, size, size);
  s.species.push_back(Species{"one", 2 * p.a1, p.rho1, false});
  s.species.push_back(Species{"two", 2 * p.a2, p.rho2, false});
  s.materials = MaterialTable(2, 0, law, law);
  const double reach = (p.a1 + p.a2) * (1 + 1e-6);
  s.add_particle(0, Vec3(0, 0, reach), Vec3(p.vx1, 0, p.vz1), Vec3(0, p.w1, 0));
  s.add_particle(1, Vec3::Zero(), Vec3(p.vx2, 0, p.vz2), Vec3(0, p.w2, 0));
  SoftSphereOptions o = hertz_options(m.young, m.poisson, 0.0);
  o.species_materials = {ElasticMaterial{m.young, m.poisson}, ElasticMaterial{m.young, m.poisson}};
  o.impact_speed = std::abs(p.vz2 - p.vz1);
  o.step_fraction = step_fraction;
  SoftSphereEngine sim(s, o);
  const ImpactResult r = run_impact(sim, 1e3 * p.a1 / o.impact_speed);
  // The engine may have reordered the particles: sphere 1 is the one of species 0.
  const int one = sim.system().particles.species[0] == 0 ? 0 : 1;
  const Vec3 v1 = one == 0 ? r.v1 : r.v2, w1 = one == 0 ? r.w1 : r.w2;
  const Vec3 v2 = one == 0 ? r.v2 : r.v1, w2 = one == 0 ? r.w2 : r.w1;
  return {v1.x(), v1.z(), w1.y(), v2.x(), v2.z(), w2.y()};
}

/// The reference for the pair.
inline Planar oracle_pair(const OracleContact& c, const PairShot& p, double steps,
                          OracleImpact* impulses = nullptr) {
  Body2D b1{0, p.a1 + p.a2, p.vx1, p.vz1, p.w1, p.a1, sphere_mass(p.a1, p.rho1)};
  Body2D b2{0, 0, p.vx2, p.vz2, p.w2, p.a2, sphere_mass(p.a2, p.rho2)};
  const OracleImpact i = oracle_impact(b1, b2, c, steps);
  if (impulses) *impulses = i;
  return {b1.vx, b1.vz, b1.spin, b2.vx, b2.vz, b2.spin};
}

/// The largest difference between two outcomes in velocities and in radius x spin, m/s.
inline double planar_difference(const Planar& a, const Planar& b, double a1, double a2 = 0) {
  return std::max({std::abs(a.vx1 - b.vx1), std::abs(a.vz1 - b.vz1), a1 * std::abs(a.w1 - b.w1),
                   std::abs(a.vx2 - b.vx2), std::abs(a.vz2 - b.vz2), a2 * std::abs(a.w2 - b.w2)});
}

}  // namespace carom::soft_test
