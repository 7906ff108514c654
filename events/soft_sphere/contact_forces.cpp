// The force of every listed contact (SoftSphereEngine::compute_forces): normal spring-dashpot,
// tangential spring with the Coulomb limit, rolling resistance; the counters and the energy
// books. The formulas are in contact_model.hpp.
//
// Energy books: the elastic energy is the springs' energy now (normal, and k_t |xi|^2 / 2).
// The dissipated energy gets the work of the normal dashpot, of the rolling torque, and of the
// tangential force less what the tangential spring stored (so: the tangential dashpot and the
// Coulomb slip), each with the end-of-step velocities (book_dissipation). The Mindlin spring's
// stiffness follows the overlap, so its energy changes at a fixed xi without any force doing
// work: that change is booked with the dissipated energy too (the known non-conservation of
// the simplified no-slip model). What remains open is the normal spring's integration error:
// kinetic + potential + elastic + dissipated closes to O(dt^2) (SoftEnergy test).
#include <algorithm>
#include <cmath>

#include "events/soft_sphere/engine.hpp"

namespace carom {

namespace {

/// What one contact gives its first body: force, and the torques about both centres.
struct ContactForce {
  Vec3 force = Vec3::Zero();     ///< On body 1 (body 2 gets -force), N.
  Vec3 torque1 = Vec3::Zero();   ///< On body 1, N m.
  Vec3 torque2 = Vec3::Zero();   ///< On body 2, N m.
  double dissipated = 0;         ///< J in this step booked now (the stiffness change).
  double elastic = 0;            ///< J stored now.
  /// The forces whose work is dissipation or goes into the tangential spring: the normal
  /// dashpot plus the whole tangential force (on body 1), and the rolling torque; their work
  /// is booked with the velocities at the end of the step (book_dissipation).
  Vec3 lossy_force = Vec3::Zero();
  Vec3 rolling_torque = Vec3::Zero();
  double spring_energy_change = 0;  ///< k_t |xi|^2 / 2 now minus before the stretch, J.
};

/// n: unit normal from body 2 to body 1; delta > 0 the overlap; g the contact velocity of body 1
/// relative to body 2; w_rel = w1 - w2; spring and overlap_before: the contact's history.
ContactForce contact_force(const PairContact& c, const Vec3& n, double delta, const Vec3& g,
                           const Vec3& w_rel, double a1, double a2, double inv_i1, double inv_i2,
                           Vec3& spring, double& overlap_before, double dt) {
  ContactForce out;
  const double approach = -g.dot(n);
  const Vec3 g_t = g + approach * n;
  const double f_n = c.normal_force(delta, approach);
  const double gamma_n = c.normal_damping_at(delta);

  // Tangential spring: turned into the present tangent plane (length kept), then stretched.
  const double k_t_before = c.tangential_stiffness_at(overlap_before);
  const double k_t = c.tangential_stiffness_at(delta);
  const double length = spring.norm();
  if (length > 0.0) {
    spring -= spring.dot(n) * n;
    const double turned = spring.norm();
    spring *= turned > 0.0 ? length / turned : 0.0;
  }
  // The stiffness follows the overlap: the energy that changes at a fixed xi.
  out.dissipated += 0.5 * (k_t_before - k_t) * length * length;
  spring += dt * g_t;
  const double gamma_t = c.tangential_damping_at(delta);
  Vec3 f_t = -k_t * spring - gamma_t * g_t;
  const double limit = c.friction * std::max(f_n, 0.0);
  const double magnitude = f_t.norm();
  if (magnitude > limit) {
    // Sliding: the force is the Coulomb limit along the trial force, and the spring alone
    // carries it (Cundall & Strack); the stretch it gives up is the slip.
    f_t *= magnitude > 0.0 ? limit / magnitude : 0.0;
    spring = k_t > 0.0 ? Vec3(-f_t / k_t) : Vec3::Zero();
  }
  out.spring_energy_change = 0.5 * k_t * spring.squaredNorm() - 0.5 * k_t * length * length;
  overlap_before = delta;
  out.force = f_n * n + f_t;
  out.lossy_force = gamma_n * approach * n + f_t;
  out.torque1 = -a1 * n.cross(f_t);
  out.torque2 = -a2 * n.cross(f_t);
  out.elastic = c.normal_energy(delta) + 0.5 * k_t * spring.squaredNorm();

  // Rolling resistance (constant directional torque), capped so that within one step it can
  // stop the relative rolling but not reverse it.
  if (c.rolling_friction > 0.0) {
    const double rolling = w_rel.norm();
    if (rolling > 0.0 && dt > 0.0) {
      const double torque = std::min(c.rolling_friction * c.reduced_radius * std::max(f_n, 0.0),
                                     rolling / (dt * (inv_i1 + inv_i2)));
      const Vec3 m = -torque / rolling * w_rel;
      out.torque1 += m;
      out.torque2 -= m;
      out.rolling_torque = m;
    }
  }
  return out;
}

}  // namespace

void SoftSphereEngine::compute_forces(double dt, bool clear) {
  ParticleStore& p = system_.particles;
  if (clear) {
    std::fill(force_.begin(), force_.end(), Vec3::Zero());
    std::fill(torque_.begin(), torque_.end(), Vec3::Zero());
  }
  const std::size_t S = system_.species.size(), W = system_.walls.size();
  double elastic = 0.0, dissipated = 0.0;
  lossy_.clear();
  TaggedImpulses& tagged = statistics_.tagged;
  std::fill(tagged.step_force.begin(), tagged.step_force.end(), Vec3::Zero());
  const std::size_t C = S + W;
  for (PairContactState& c : list_.pairs()) {
    const std::int32_t i = c.owner, j = c.partner;
    Vec3 d = p.position[i] - p.position[j];
    system_.domain.minimum_image(d);
    const double a_i = p.radius[i], a_j = p.radius[j];
    const double reach = a_i + a_j;
    const double distance2 = d.squaredNorm();
    const std::size_t si = p.species[i], sj = p.species[j];
    if (distance2 >= reach * reach) {
      if (c.touching) {
        c.touching = false;
        c.spring = Vec3::Zero();
        const double duration = time_ + dt - c.since;
        durations_.count[si * S + sj] += 1;
        durations_.total[si * S + sj] += duration;
        if (si != sj) {
          durations_.count[sj * S + si] += 1;
          durations_.total[sj * S + si] += duration;
        }
      }
      continue;
    }
    const double distance = std::sqrt(distance2);
    const Vec3 n = d / distance;
    const double delta = reach - distance;
    if (!c.touching) {
      c.touching = true;
      c.since = time_ + dt;
      c.spring = Vec3::Zero();
      c.overlap = 0.0;
      // An impact when the pair approaches faster than the impact speed as the contact begins.
      statistics_.count_pair(si, sj, system_.is_impact(-(p.velocity[i] - p.velocity[j]).dot(n)));
    }
    const double smaller = std::min(a_i, a_j);
    worst_overlap_ = std::max(worst_overlap_, delta / smaller);
    if (delta > options_.max_overlap * smaller) fail_overlap(i, j, delta, smaller);
    const Vec3 g = p.velocity[i] - p.velocity[j] - (a_i * p.spin[i] + a_j * p.spin[j]).cross(n);
    const ContactForce f = contact_force(pair_contact(si, sj), n, delta, g, p.spin[i] - p.spin[j], a_i,
                                         a_j, inverse_inertia_[i], inverse_inertia_[j], c.spring,
                                         c.overlap, dt);
    force_[i] += f.force;
    force_[j] -= f.force;
    if (tagged.any()) {
      if (const std::int32_t k = tagged.slot_of[i]; k >= 0)
        tagged.step_force[k * C + sj] += f.force;
      if (const std::int32_t k = tagged.slot_of[j]; k >= 0)
        tagged.step_force[k * C + si] -= f.force;
    }
    torque_[i] += f.torque1;
    torque_[j] += f.torque2;
    elastic += f.elastic;
    dissipated += f.dissipated - f.spring_energy_change;
    if (dt > 0.0) lossy_.push_back({i, j, n, f.lossy_force, f.rolling_torque});
    const double impulse = f.force.norm() * dt;
    statistics_.pair_impulse[si * S + sj] += impulse;
    if (si != sj) statistics_.pair_impulse[sj * S + si] += impulse;
    statistics_.virial += d * (dt * f.force).transpose();
  }
  for (WallContactState& c : list_.wall_pairs()) {
    const std::int32_t i = c.particle;
    const Wall& wall = system_.walls[c.wall];
    const double a = p.radius[i];
    const double gap = wall.gap(p.position[i], a);
    const std::size_t s = p.species[i];
    if (gap >= 0.0) {
      c.touching = false;
      c.spring = Vec3::Zero();
      continue;
    }
    const double delta = -gap;
    if (!c.touching) {
      c.touching = true;
      c.since = time_ + dt;
      c.spring = Vec3::Zero();
      c.overlap = 0.0;
      // An impact when the particle approaches faster than the impact speed as the contact begins.
      statistics_.count_wall(s, c.wall,
                             system_.is_impact(-p.velocity[i].dot(wall.contact_normal(p.position[i]))));
    }
    worst_overlap_ = std::max(worst_overlap_, delta / a);
    if (delta > options_.max_overlap * a) fail_overlap(i, -1 - c.wall, delta, a);
    const Vec3 n = wall.contact_normal(p.position[i]);
    const Vec3 g = p.velocity[i] - (a * p.spin[i]).cross(n);
    const ContactForce f = contact_force(wall_contact(s, c.wall), n, delta, g, p.spin[i], a, 0.0,
                                         inverse_inertia_[i], 0.0, c.spring, c.overlap, dt);
    force_[i] += f.force;
    if (tagged.any())
      if (const std::int32_t k = tagged.slot_of[i]; k >= 0)
        tagged.step_force[k * C + S + c.wall] += f.force;
    torque_[i] += f.torque1;
    elastic += f.elastic;
    dissipated += f.dissipated - f.spring_energy_change;
    if (dt > 0.0) lossy_.push_back({i, -1, n, f.lossy_force, f.rolling_torque});
    statistics_.wall_impulse[c.wall] -= dt * f.force;
  }
  elastic_ = elastic;
  statistics_.dissipated_energy += dissipated;
}

void SoftSphereEngine::book_dissipation(double dt) {
  // With velocity Verlet the force of step k changes the kinetic energy by F . v(t_k) dt exactly
  // (v(t_k) the mean of the half-step velocities on either side): the lossy forces' work is
  // booked with the velocities at the end of the step, not the half-step ones they were
  // computed with (which would be an O(dt / t_c) error in the books).
  const ParticleStore& p = system_.particles;
  double work = 0.0;
  for (const LossyContact& c : lossy_) {
    const double a_i = p.radius[c.first];
    Vec3 g = p.velocity[c.first] - a_i * p.spin[c.first].cross(c.normal);
    Vec3 w_rel = p.spin[c.first];
    if (c.second >= 0) {
      g -= p.velocity[c.second] + p.radius[c.second] * p.spin[c.second].cross(c.normal);
      w_rel -= p.spin[c.second];
    }
    work += c.force.dot(g) + c.rolling_torque.dot(w_rel);
  }
  statistics_.dissipated_energy -= work * dt;
}

}  // namespace carom
