// One particle's Monte Carlo step: exact flights, exact wall impacts, and collisions with
// fictitious partners as a thinned Poisson process (engine.hpp says why).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <sstream>

#include "events/laws/walton.hpp"
#include "events/monte_carlo/engine.hpp"
#include "events/monte_carlo/partner_sampling.hpp"

namespace carom {

namespace {
/// Flies r, v over s seconds of the flight f (exact: ballistic when f.rate = 0). With `gas`
/// (relax flights: f holds the gas forces) the work per unit mass that the gas forces did on the
/// way is added to `work`, J/kg (RelaxFlight::move_booking_gas_work: the exact integral, and
/// the same r, v bit for bit).
void fly(Vec3& r, Vec3& v, const RelaxFlight& f, double s, bool gas, const Vec3& gravity,
         double& work) {
  if (s <= 0.0) return;
  if (gas) {
    work += f.move_booking_gas_work(r, v, s, gravity);
    return;
  }
  r += f.displacement(v, s);
  v = f.velocity(v, s);
}

/// Kinetic energy of a body, J.
double kinetic_energy(const Vec3& v, const Vec3& w, double mass, double inertia) {
  return 0.5 * mass * v.squaredNorm() + 0.5 * inertia * w.squaredNorm();
}

/// Standard deviations of a Gaussian velocity whose magnitude of deviation almost never exceeds
/// this many times sqrt(sum of variances): P(chi_3 > 5) = 1.6e-5 for an isotropic one.
constexpr double kSpreadBound = 5.0;
}  // namespace

void MonteCarloEngine::step_particle(std::size_t i, std::int32_t cell) {
  const ParticleStore& p = system_.particles;
  Vec3 r = start_position_[i], v = start_velocity_[i], w = start_spin_[i];
  const std::uint32_t s = p.species[i];
  end_gas_work_[i] = 0.0;
  if (system_.species[s].fixed) {
    end_position_[i] = r;
    end_velocity_[i] = v;
    end_spin_[i] = w;
    return;
  }
  const RelaxFlight f = flight_of(i);
  // Relax flights carry the gas forces: their work is booked flight by flight (J/kg since the
  // particle's last logged event, handed to the next event or to end_gas_work_).
  const bool gas = options_.flight_model == FlightModel::Relax;
  const Vec3& gravity = system_.flight.gravity;
  double flown_work = 0.0;
  const double a = p.radius[i], mass = p.mass[i], inertia = p.inertia[i];
  const std::size_t species = system_.species.size();
  const bool mean_velocity = options_.frequency == CollisionFrequency::MeanVelocity;
  const bool cell_particle = options_.partner == PartnerModel::CellParticle;
  const bool cell_mean = options_.partner == PartnerModel::CellMean;

  // The partners of each species in this particle's cell, and the part of the candidate rate
  // that does not depend on speed: c pi (R1 + R0)^2 n g.
  const OwnContribution own{s, a, v, w};
  std::vector<PartnerStatistics>& partners = scratch_.partners;
  std::vector<double>& rate_per_speed = scratch_.rate_per_speed;
  std::vector<double>& bound = scratch_.bound;
  std::vector<double>& candidate_rate = scratch_.candidate_rate;
  partners.resize(species);
  rate_per_speed.assign(species, 0.0);
  bound.assign(species, 0.0);
  candidate_rate.assign(species, 0.0);
  const double phi = options_.contact_value == ContactValue::Enskog ? grid_.solid_fraction(cell) : 0.0;
  const double xi2 = options_.contact_value == ContactValue::Enskog ? grid_.xi2(cell) : 0.0;
  for (std::size_t t = 0; t < species; ++t) {
    partners[t] = grid_.partners(cell, static_cast<std::uint32_t>(t), &own);
    if (partners[t].count < 0.5) continue;
    const double reach = a + partners[t].mean_radius;
    rate_per_speed[t] = (mean_velocity ? std::numbers::sqrt2 : 1.0) * std::numbers::pi * reach * reach *
                        partners[t].number_density *
                        contact_value(options_.contact_value, phi, xi2, 2.0 * a, 2.0 * partners[t].mean_radius);
  }

  // A partner of species t: its velocity, and its spin (CellParticle: one of the cell's other
  // particles of species t at random, as at the step start; Gaussian: the mean spin; CellMean:
  // the mean velocity and spin).
  Vec3 partner_spin = Vec3::Zero();
  auto draw_partner = [&](std::size_t t) -> Vec3 {
    if (cell_mean) {
      partner_spin = partners[t].mean_spin;
      return partners[t].mean_velocity;
    }
    if (!cell_particle) {
      partner_spin = partners[t].mean_spin;
      return sample_partner_velocity(partners[t], rng_);
    }
    const std::span<const std::uint32_t> list = grid_.members(cell, static_cast<std::uint32_t>(t));
    const std::size_t others = list.size() - (t == s ? 1 : 0);
    const std::size_t k =
        std::min(others - 1, static_cast<std::size_t>(rng_.uniform() * double(others)));
    std::uint32_t j = list[k];
    if (j == i) j = list.back();  // i is not last, so the others stay equally likely
    partner_spin = start_spin_[j];
    return start_velocity_[j];
  };

  double clock = step_start_;
  int instant_wall_impacts = 0;
  std::size_t events_here = 0;
  for (;;) {
    const double remaining = step_end_ - clock;
    if (!(remaining > 0.0)) break;
    // How far V1 can move over the rest of the step: |a0| s bounds it (and, with drag, the
    // distance to the asymptotic velocity: v(s) stays on the segment between them).
    double drift = f.acceleration(v).norm() * remaining;
    if (f.rate > 0.0) drift = std::min(drift, (f.drive / f.rate - v).norm());
    double total_rate = 0.0;
    for (std::size_t t = 0; t < species; ++t) {
      if (rate_per_speed[t] == 0.0) {
        candidate_rate[t] = 0.0;
        continue;
      }
      // CellParticle: |V1 - V0| <= |V1 - <V>| + |V0 - <V>| with <V> the mean of every particle
      // of the cell, an exact bound.
      if (mean_velocity || cell_mean)
        bound[t] = (v - partners[t].mean_velocity).norm() + drift;
      else if (cell_particle)
        bound[t] = (v - grid_.mean_velocity(cell, static_cast<std::uint32_t>(t))).norm() + drift +
                   grid_.largest_deviation(cell, static_cast<std::uint32_t>(t));
      else
        bound[t] = (v - partners[t].mean_velocity).norm() + drift +
                   kSpreadBound * partners[t].velocity_std.norm();
      candidate_rate[t] = rate_per_speed[t] * bound[t];
      total_rate += candidate_rate[t];
    }
    const double candidate_in = total_rate > 0.0 ? -std::log1p(-rng_.uniform()) / total_rate : kNever;
    double wall_in = kNever;
    std::int32_t wall = -1;
    for (std::size_t k = 0; k < system_.walls.size(); ++k) {
      const double contact = f.rate == 0.0
                                 ? ballistic_wall_contact(system_.walls[k], r, v, a, f.drive)
                                 : relax_wall_contact(system_.walls[k], r, v, a, f, remaining);
      if (contact < wall_in) {
        wall_in = contact;
        wall = static_cast<std::int32_t>(k);
      }
    }
    if (candidate_in >= remaining && wall_in >= remaining) break;

    if (++events_here > 100000) {
      std::ostringstream out;
      out << "particle " << p.id[i] << " at " << r.transpose() << " m had 100000 collision trials and wall impacts ("
          << (log_.size() - log_begin_[i]) << " impacts and collisions) in one step at t = " << clock
          << " s; reduce [monte_carlo] time_step";
      throw MethodFailure("monte_carlo_event_stall", out.str());
    }
    if (wall_in <= candidate_in) {
      fly(r, v, f, wall_in, gas, gravity, flown_work);
      clock = std::min(clock + wall_in, step_end_);
      if (wall_in == 0.0 && ++instant_wall_impacts > 1000) {
        std::ostringstream out;
        out << "particle " << p.id[i] << " at " << r.transpose() << " m hit walls 1000 times at t = " << clock
            << " s without moving on (trapped in a wall corner?)";
        throw MethodFailure("monte_carlo_wall_stall", out.str());
      }
      const Vec3 normal = system_.walls[wall].contact_normal(r);
      Vec3 wall_velocity = Vec3::Zero(), wall_spin = Vec3::Zero();
      // Slow impacts are elastic (the collapse remedy of core/DESIGN.md, "Collision laws and
      // collapse"): a particle at rest on a floor would otherwise bounce infinitely often within a
      // step.
      ContactLaw law = system_.materials.wall(s, wall);
      if (std::abs(v.dot(normal)) < elastic_below_speed_) law.restitution = 1.0;
      const double approach = -v.dot(normal);
      const CollisionOutcome outcome =
          collide(law, normal, ContactBody{v, w, 1.0 / mass, a, 1.0 / inertia},
                  ContactBody{wall_velocity, wall_spin, 0.0, 0.0, 0.0});
      log_.push_back(StepEvent{clock, r, v, w, -1 - wall, outcome.impulse, Vec3::Zero(),
                               outcome.dissipated, approach, mass * flown_work});
      flown_work = 0.0;
      continue;
    }

    fly(r, v, f, candidate_in, gas, gravity, flown_work);
    clock = std::min(clock + candidate_in, step_end_);
    // Which species this candidate is of, in proportion to the candidate rates.
    double pick = rng_.uniform() * total_rate;
    std::size_t t = 0;
    while (t + 1 < species && (candidate_rate[t] == 0.0 || pick >= candidate_rate[t])) {
      pick -= candidate_rate[t];
      ++t;
    }
    const PartnerStatistics& partner = partners[t];
    Vec3 partner_velocity = partner.mean_velocity;
    double speed = 0.0;
    if (mean_velocity) {
      speed = (v - partner.mean_velocity).norm();
    } else {
      partner_velocity = draw_partner(t);
      speed = (v - partner_velocity).norm();
    }
    if (speed > bound[t]) ++step_bound_exceeded_;
    if (rng_.uniform() * bound[t] >= speed) continue;  // thinned: no collision
    if (mean_velocity) partner_velocity = draw_partner(t);
    const Vec3 relative = v - partner_velocity;
    if (relative.squaredNorm() == 0.0) continue;
    const Vec3 normal = sample_impact_normal(relative, rng_);

    const Species& kind = system_.species[t];
    const double partner_radius = partner.mean_radius;
    const double partner_mass = kind.density * 4.0 / 3.0 * std::numbers::pi * std::pow(partner_radius, 3);
    const double partner_inertia = 0.4 * partner_mass * partner_radius * partner_radius;
    const double before = kinetic_energy(v, w, mass, inertia);
    const double approach = -relative.dot(normal);
    const CollisionOutcome outcome =
        collide(system_.materials.pair(s, t), normal, ContactBody{v, w, 1.0 / mass, a, 1.0 / inertia},
                ContactBody{partner_velocity, partner_spin, kind.fixed ? 0.0 : 1.0 / partner_mass, partner_radius,
                            kind.fixed ? 0.0 : 1.0 / partner_inertia});
    log_.push_back(StepEvent{clock, r, v, w, static_cast<std::int32_t>(t), outcome.impulse,
                             (a + partner_radius) * normal,
                             before - kinetic_energy(v, w, mass, inertia), approach, mass * flown_work});
    flown_work = 0.0;
  }
  fly(r, v, f, step_end_ - clock, gas, gravity, flown_work);
  end_gas_work_[i] = mass * flown_work;
  end_position_[i] = r;
  end_velocity_[i] = v;
  end_spin_[i] = w;
}

}  // namespace carom
