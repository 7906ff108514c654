#pragma once
// Small systems for the soft-sphere tests: two spheres, a sphere and a wall, and how to step
// them one time step at a time.
#include <cmath>
#include <numbers>

#include "core/system.hpp"
#include "events/soft_sphere/engine.hpp"

namespace carom::soft_test {

/// One species (diameter d, density rho), no walls unless added, no gravity, a big box.
inline System empty_system(double d, double rho, const ContactLaw& law, int walls = 0) {
  System s;
  s.domain.lower = Vec3(-1, -1, -1);
  s.domain.upper = Vec3(1, 1, 1);
  s.species.push_back(Species{"glass", d, rho, false});
  if (walls > 0) s.walls.push_back(Wall::plane("floor", Vec3(0, 0, 0), Vec3::UnitZ()));
  s.materials = MaterialTable(1, s.walls.size(), law, law);
  return s;
}

inline SoftSphereOptions hertz_options(double young, double poisson, double step) {
  SoftSphereOptions o;
  o.model = ContactModel::HertzMindlin;
  o.species_materials = {ElasticMaterial{young, poisson}};
  o.time_step = step;
  o.max_overlap = 0.5;
  return o;
}

inline SoftSphereOptions linear_options(double stiffness, double step) {
  SoftSphereOptions o;
  o.model = ContactModel::Linear;
  o.stiffness = stiffness;
  o.time_step = step;
  o.max_overlap = 0.5;
  return o;
}

/// What one binary impact gave: velocities and spins after, the peak overlap, the duration.
struct ImpactResult {
  Vec3 v1, v2, w1, w2;
  double peak_overlap = 0;  ///< m
  double duration = 0;      ///< s (steps with an overlap, times the step)
};

/// Steps `sim` until the contact is over and every sphere moves apart (at most max_time),
/// tracking the overlap of particle 0 with particle 1 (or with the floor when one particle).
inline ImpactResult run_impact(SoftSphereEngine& sim, double max_time) {
  ImpactResult out;
  const double dt = sim.time_step();
  bool touched = false;
  while (sim.time() < max_time) {
    sim.run_until(sim.time() + dt);
    double overlap;
    if (sim.particle_count() == 2) {
      overlap = sim.system().particles.radius[0] + sim.system().particles.radius[1] -
                (sim.position(0) - sim.position(1)).norm();
    } else {
      overlap = -sim.system().walls[0].gap(sim.position(0), sim.system().particles.radius[0]);
    }
    out.peak_overlap = std::max(out.peak_overlap, overlap);
    if (overlap > 0) {
      touched = true;
      out.duration += dt;
    }
    if (touched && overlap < 0) break;
  }
  out.v1 = sim.velocity(0);
  out.w1 = sim.spin(0);
  if (sim.particle_count() == 2) {
    out.v2 = sim.velocity(1);
    out.w2 = sim.spin(1);
  }
  return out;
}

}  // namespace carom::soft_test
