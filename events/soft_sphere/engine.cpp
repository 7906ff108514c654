#include "events/soft_sphere/engine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "events/restored_actions.hpp"

namespace carom {

namespace {

std::string seconds(double t) {
  std::ostringstream out;
  out.precision(4);
  out << t << " s";
  return out.str();
}

}  // namespace

SoftSphereEngine::SoftSphereEngine(System system, SoftSphereOptions options)
    : system_(std::move(system)), options_(std::move(options)), list_(system_.domain, 0.0) {
  sort_particles();
  setup();
  flights_.assign(system_.particles.size(), RelaxFlight{0.0, system_.flight.gravity});
  hold_fixed_particles();
  list_.build(system_.particles.position, system_.particles.radius, system_.walls);
  compute_forces(0.0, true);
  const Energies e = energies();
  energy_start_ = e.total();
  energy_scale_ = e.translational + e.rotational + e.elastic;
}

void SoftSphereEngine::setup() {
  const std::size_t S = system_.species.size(), W = system_.walls.size();
  const ParticleStore& p = system_.particles;
  const std::size_t n = p.size();
  if (options_.model == ContactModel::HertzMindlin && options_.species_materials.size() != S)
    throw std::invalid_argument("the Hertz–Mindlin model needs young_modulus and poisson_ratio for "
                                "every species");
  if (!(options_.skin > 0.0)) throw std::invalid_argument("soft_sphere.skin must be > 0");
  double smallest = std::numeric_limits<double>::infinity();
  for (const Species& s : system_.species) smallest = std::min(smallest, s.diameter);
  list_ = NeighbourList(system_.domain, options_.skin * smallest);

  // Which species (and species-wall pairs) occur: only they bound the step.
  std::vector<std::size_t> present(S, 0);  // particles per species
  double fastest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    ++present[p.species[i]];
    fastest = std::max(fastest, p.velocity[i].norm());
  }
  for (std::uint32_t s : system_.entering_species) present.at(s) += 2;  // as if present, pairs too
  fastest = std::max(fastest, system_.entering_speed);
  const Vec3 g = system_.flight.gravity;
  double fall = 0.0;
  if (g.norm() > 0.0) {
    const Vec3 length = system_.domain.length();
    const Vec3 direction = g.normalized();
    fall = std::abs(direction.x()) * length.x() + std::abs(direction.y()) * length.y() +
           std::abs(direction.z()) * length.z();
  }
  impact_speed_ = options_.impact_speed > 0.0
                      ? options_.impact_speed
                      : std::max(2.0 * fastest, std::sqrt(2.0 * g.norm() * fall));
  if (!(impact_speed_ > 0.0)) impact_speed_ = 1.0;

  auto material = [&](std::size_t s) {
    return options_.model == ContactModel::HertzMindlin ? options_.species_materials[s]
                                                        : ElasticMaterial{1.0, 0.0};
  };
  auto species_mass = [&](std::size_t s) {
    return system_.species[s].fixed ? std::numeric_limits<double>::infinity()
                                    : system_.species[s].mass();
  };
  pair_contacts_.assign(S * S, PairContact{});
  wall_contacts_.assign(S * W, PairContact{});
  shortest_contact_time_ = std::numeric_limits<double>::infinity();
  double stability_limit = std::numeric_limits<double>::infinity();
  std::string limiting;
  auto consider = [&](const PairContact& c, const std::string& what) {
    const double t_c = c.contact_time(impact_speed_);
    const double omega = std::sqrt(c.stiffness_at(c.peak_overlap(impact_speed_)) / c.reduced_mass);
    if (t_c < shortest_contact_time_) {
      shortest_contact_time_ = t_c;
      limiting = what;
    }
    stability_limit = std::min(stability_limit, 2.0 / omega);
  };
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t t = 0; t < S; ++t) {
      const Species &a = system_.species[s], &b = system_.species[t];
      if (a.fixed && b.fixed) continue;
      const ContactLaw& law = system_.materials.pair(s, t);
      const std::string what = "species '" + a.name + "' with '" + b.name + "'";
      try {
        pair_contacts_[s * S + t] =
            make_pair_contact(a.radius(), species_mass(s), material(s), b.radius(), species_mass(t),
                              material(t), law.restitution, law.friction, options_);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(what + ": " + e.what());
      }
      if (present[s] > (s == t ? 1u : 0u) && present[t] > 0) consider(pair_contacts_[s * S + t], what);
    }
  for (std::size_t s = 0; s < S; ++s)
    for (std::size_t w = 0; w < W; ++w) {
      const Species& a = system_.species[s];
      if (a.fixed) continue;
      const ContactLaw& law = system_.materials.wall(s, w);
      const std::string what = "species '" + a.name + "' with wall '" + system_.walls[w].name + "'";
      const ElasticMaterial wall_material =
          w < options_.wall_materials.size() && options_.wall_materials[w] ? *options_.wall_materials[w]
                                                                          : material(s);
      try {
        wall_contacts_[s * W + w] = make_wall_contact(a.radius(), a.mass(), material(s), wall_material,
                                                      law.restitution, law.friction, options_);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(what + ": " + e.what());
      }
      if (present[s] > 0) consider(wall_contacts_[s * W + w], what);
    }
  if (!std::isfinite(shortest_contact_time_)) shortest_contact_time_ = 0.0;
  time_step_ = options_.time_step > 0.0 ? options_.time_step
                                        : options_.step_fraction * shortest_contact_time_;
  if (!(time_step_ > 0.0))
    throw std::invalid_argument("no contact bounds the step (no moving particles?): set "
                                "soft_sphere.time_step");
  if (time_step_ > stability_limit)
    throw std::invalid_argument(
        "time step " + seconds(time_step_) + " is above the stability limit of velocity Verlet, " +
        seconds(stability_limit) + " (2 / omega of the stiffest contact, " + limiting +
        ", at impact speed " + std::to_string(impact_speed_) + " m/s); the contact lasts " +
        seconds(shortest_contact_time_) + ": take at most " + seconds(stability_limit) +
        ", better " + seconds(0.02 * shortest_contact_time_) + " (1/50 of the contact)");

  inverse_mass_.assign(n, 0.0);
  inverse_inertia_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (!system_.species[p.species[i]].fixed) {
      inverse_mass_[i] = 1.0 / p.mass[i];
      inverse_inertia_[i] = 1.0 / p.inertia[i];
    }
  force_.assign(n, Vec3::Zero());
  torque_.assign(n, Vec3::Zero());
  statistics_.resize(S, W);
  durations_.count.assign(S * S, 0);
  durations_.total.assign(S * S, 0.0);
}

void SoftSphereEngine::sort_particles() {
  // Neighbours in space become neighbours in memory: the force loop then finds a particle's
  // partners in cache. Cells of about one largest diameter, ordered along a Morton (Z-order)
  // curve: a pair's partner sits within a few hundred entries of its owner in most cases,
  // where a row-by-row order puts the next layer of cells a whole layer's particles away (at
  // 100 000 particles that layer, with its velocities and forces, outgrew the 1 MB L2 cache:
  // 96 ns per particle-step against 61 at 10 000). Ties keep the given order, so the result is
  // deterministic. (Once, here: particle indices stay fixed for the method's life, as the
  // interface promises; ids are unchanged.)
  ParticleStore& p = system_.particles;
  const std::size_t n = p.size();
  if (n < 2) return;
  double largest = 0.0;
  for (double a : p.radius) largest = std::max(largest, a);
  const Domain& d = system_.domain;
  constexpr std::int64_t kMaxCells = std::int64_t{1} << 21;  // 21 bits per axis in a 64-bit key
  std::array<std::int64_t, 3> cells{};
  for (int k = 0; k < 3; ++k)
    cells[k] = std::clamp<std::int64_t>(static_cast<std::int64_t>(d.length()[k] / (2.0 * largest)),
                                        1, kMaxCells);
  // Spreads the 21 low bits of v to every third bit.
  auto spread = [](std::uint64_t v) {
    v &= 0x1fffff;
    v = (v | v << 32) & 0x1f00000000ffff;
    v = (v | v << 16) & 0x1f0000ff0000ff;
    v = (v | v << 8) & 0x100f00f00f00f00f;
    v = (v | v << 4) & 0x10c30c30c30c30c3;
    v = (v | v << 2) & 0x1249249249249249;
    return v;
  };
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<std::uint64_t, 3> c{};
    for (int k = 0; k < 3; ++k)
      c[k] = static_cast<std::uint64_t>(std::clamp<std::int64_t>(
          static_cast<std::int64_t>((p.position[i][k] - d.lower[k]) / d.length()[k] * cells[k]), 0,
          cells[k] - 1));
    key[i] = spread(c[0]) | spread(c[1]) << 1 | spread(c[2]) << 2;
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] < key[b]; });
  p.permute(order);
}

void SoftSphereEngine::hold_fixed_particles() {
  ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (inverse_mass_[i] == 0.0) {
      p.velocity[i] = p.spin[i] = Vec3::Zero();
      flights_[i] = RelaxFlight{};
    }
}

void SoftSphereEngine::add_periodic_action(std::string name, double first_time, double interval,
                                           std::function<void()> action) {
  if (!(interval > 0.0)) throw std::invalid_argument(name + ": the interval must be positive");
  first_time = restored_next_time(restored_action_times_, name, first_time, time_, interval);
  actions_.push_back(SteppedAction{std::move(name), first_time, interval, std::move(action), {}});
}

void SoftSphereEngine::add_synchronising_action(std::string name, double first_time, double interval,
                                                std::function<void(GlobalStep&)> step) {
  if (!(interval > 0.0)) throw std::invalid_argument(name + ": the interval must be positive");
  if (!(first_time >= time_))
    throw std::invalid_argument(name + ": the first step is before the current time");
  first_time = restored_next_time(restored_action_times_, name, first_time, time_, interval);
  actions_.push_back(SteppedAction{std::move(name), first_time, interval, {}, std::move(step)});
}

void SoftSphereEngine::fire_due_actions(double t) {
  // In registration order (the fluid step is registered first), each as often as it is due.
  for (bool fired = true; fired;) {
    fired = false;
    for (SteppedAction& a : actions_) {
      if (a.next_time > t) continue;
      fired = true;
      ParticleStore& p = system_.particles;
      std::fill(p.clock.begin(), p.clock.end(), time_);
      if (a.step) {
        GlobalStep global{time_, p, flights_};
        a.step(global);
        if (flights_.size() != p.size() || force_.size() != p.size())
          throw std::logic_error(a.name + " changed the number of particles or flights");
        if (!global.change.empty()) apply_change(global.change);
        gas_forces_ = true;  // (a flow step's flights are gravity alone: the same forces)
        hold_fixed_particles();
        for (std::size_t i = 0; i < p.size(); ++i)
          if (flights_[i].rate * time_step_ > 0.5)
            throw MethodFailure(
                "soft_sphere_unstable",
                "the drag relaxation time of particle " + std::to_string(p.id[i]) + " (" +
                    seconds(1.0 / flights_[i].rate) + ") is below twice the time step " +
                    seconds(time_step_) + ": the explicit drag would be inaccurate or unstable; "
                    "take soft_sphere.time_step below " + seconds(0.5 / flights_[i].rate));
      } else {
        a.action();
      }
      a.next_time += a.interval;
    }
  }
}

double SoftSphereEngine::stop_time(double t) const {
  // The steps run_until would take (the same additions), up to the first action on the way.
  double next = time_;
  double action = std::numeric_limits<double>::infinity();
  for (const SteppedAction& a : actions_) action = std::min(action, a.next_time);
  while (next < t && next < action) next += time_step_;
  return std::min(next, std::max(action, time_));
}

bool SoftSphereEngine::run_until(double t_end) {
  for (;;) {
    fire_due_actions(time_);
    if (time_ >= t_end) return true;
    if (stop_flag_ != nullptr && *stop_flag_) return false;
    double target = t_end;
    for (const SteppedAction& a : actions_) target = std::min(target, a.next_time);
    // A whole step unless the target comes first; a target one step away (up to round-off in
    // its sum) is reached with a whole step, so that stopping at a step boundary (stop_time)
    // changes no bit of the run.
    const double remaining = target - time_;
    if (remaining < time_step_ * (1.0 - 1e-9)) {
      step(remaining);
      time_ = target;
    } else {
      step(time_step_);
      time_ += time_step_;
      if (std::abs(target - time_) <= 1e-9 * time_step_) time_ = target;
    }
    if (++steps_ % 64 == 0) check_energy();
  }
}

void SoftSphereEngine::tag_bodies(const std::vector<std::uint64_t>& ids) {
  CollisionMethod::tag_bodies(ids);
  // Before the first step the forces of t = 0 are computed again with the bodies tagged: with
  // dt = 0 that changes no spring, counter or energy (contacts of t = 0 are already begun).
  if (steps_ == 0 && statistics_.tagged.any()) compute_forces(0.0, true);
}

template <bool kDrift>
double SoftSphereEngine::half_kick(double dt) {
  // kDrift: the step's first half kick, the drift and the clearing of the forces in one pass
  // over the particles (each particle's arithmetic is that of three passes, in the same order;
  // one pass reads and writes its arrays once, which at 1e5 particles no longer fit the cache).
  // Returns the largest squared speed of the drift (0 without it).
  ParticleStore& p = system_.particles;
  const double h = 0.5 * dt;
  if (statistics_.tagged.any()) statistics_.tagged.book_half_step(h);
  const Vec3 g = system_.flight.gravity;
  const std::size_t n = p.size();
  const Domain& d = system_.domain;
  double fastest2 = 0.0;
  // The drift of particle i by its half-step velocity, wrapped into a periodic box.
  auto drift = [&](std::size_t i) {
    Vec3& r = p.position[i];
    const Vec3& v = p.velocity[i];
    r += dt * v;
    fastest2 = std::max(fastest2, v.squaredNorm());
    for (int k = 0; k < 3; ++k) {
      if (!d.periodic[k]) continue;
      const double length = d.upper[k] - d.lower[k];
      if (r[k] >= d.upper[k])
        r[k] -= length;
      else if (r[k] < d.lower[k])
        r[k] += length;
    }
  };
  if (!gas_forces_) {  // gravity alone (no fluid step yet): no drag, no gas work
    const Vec3 kick = h * g;
    for (std::size_t i = 0; i < n; ++i) {
      const double inv_m = inverse_mass_[i];
      if (inv_m != 0.0) {
        p.velocity[i] += (h * inv_m) * force_[i] + kick;
        p.spin[i] += (h * inverse_inertia_[i]) * torque_[i];
        if constexpr (kDrift) drift(i);
      }
      if constexpr (kDrift) force_[i] = torque_[i] = Vec3::Zero();
    }
    return fastest2;
  }
  double work = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (inverse_mass_[i] != 0.0) {
      const Vec3 v0 = p.velocity[i];
      const Vec3 body = flights_[i].acceleration(v0);
      const Vec3 v1 = v0 + h * (force_[i] * inverse_mass_[i] + body);
      // The gas force m (a - g) times the mean velocity over the half step.
      work += p.mass[i] * (body - g).dot(v0 + v1) * (0.5 * h);
      p.velocity[i] = v1;
      p.spin[i] += h * inverse_inertia_[i] * torque_[i];
      if constexpr (kDrift) drift(i);
    }
    if constexpr (kDrift) force_[i] = torque_[i] = Vec3::Zero();
  }
  gas_work_ += work;
  return fastest2;
}

void SoftSphereEngine::step(double dt) {
  ParticleStore& p = system_.particles;
  // The list stays valid while no particle can have moved half the skin since it was built:
  // every step moves each particle by its half-step velocity times dt, so the sum over the
  // steps of the largest such displacement bounds them all (cheaper than comparing each
  // position with its reference, and never later than that test would rebuild).
  const double fastest2 = half_kick<true>(dt);
  travelled_ += std::sqrt(fastest2) * dt;
  if (travelled_ > 0.5 * list_.skin() || list_.reference_positions().size() != p.size()) {
    list_.build(p.position, p.radius, system_.walls);
    travelled_ = 0.0;
  }
  compute_forces(dt, false);
  half_kick<false>(dt);
  book_dissipation(dt);
  ++statistics_.events;
}

Energies SoftSphereEngine::energies() const {
  Energies e;
  const ParticleStore& p = system_.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (inverse_mass_[i] == 0.0) continue;
    e.translational += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
    e.rotational += 0.5 * p.inertia[i] * p.spin[i].squaredNorm();
    e.potential -= p.mass[i] * system_.flight.gravity.dot(p.position[i]);
  }
  e.elastic = elastic_;
  e.dissipated = statistics_.dissipated_energy;
  e.gas_work = gas_work_;
  e.flow = flow_energy_;
  return e;
}

void SoftSphereEngine::check_energy() {
  const Vec3 g = system_.flight.gravity;
  for (int k = 0; k < 3; ++k)
    if (system_.domain.periodic[k] && g[k] != 0.0) return;  // the potential jumps at each fold
  const Energies e = energies();
  energy_scale_ = std::max(energy_scale_, e.translational + e.rotational + e.elastic);
  const double drift = e.total() - energy_start_;
  if (!(drift <= options_.max_energy_drift * energy_scale_) && energy_scale_ > 0.0) {
    // The stiffest contact at the deepest overlap seen sets the stability limit.
    double limit = std::numeric_limits<double>::infinity();
    for (const PairContactState& c : list_.pairs()) {
      if (!c.touching) continue;
      const ParticleStore& p = system_.particles;
      Vec3 d = p.position[c.owner] - p.position[c.partner];
      system_.domain.minimum_image(d);
      const double overlap = p.radius[c.owner] + p.radius[c.partner] - d.norm();
      const PairContact& k = pair_contact(p.species[c.owner], p.species[c.partner]);
      limit = std::min(limit, 2.0 / std::sqrt(k.stiffness_at(std::max(overlap, 0.0)) / k.reduced_mass));
    }
    std::ostringstream out;
    out.precision(4);
    out << "soft spheres: the energy grew by " << drift / energy_scale_
        << " of the largest kinetic + elastic energy (limit soft_sphere.max_energy_drift = "
        << options_.max_energy_drift << ") by t = " << time_ << " s, step " << steps_
        << ": the time step " << time_step_ << " s is too large for the stiffness";
    if (std::isfinite(limit))
      out << " (the stiffest contact now allows at most " << limit << " s)";
    out << "; the binary contact lasts " << shortest_contact_time_ << " s at " << impact_speed_
        << " m/s: take soft_sphere.time_step <= " << 0.02 * shortest_contact_time_
        << " s (1/50 of it), or raise soft_sphere.impact_speed if impacts are faster";
    throw MethodFailure("soft_sphere_unstable", out.str());
  }
}

void SoftSphereEngine::fail_overlap(std::int32_t i, std::int32_t j, double overlap, double radius) const {
  const ParticleStore& p = system_.particles;
  std::ostringstream out;
  out.precision(4);
  out << "soft spheres: the overlap of particle " << p.id[i];
  if (j >= 0) out << " with particle " << p.id[j];
  else out << " with wall '" << system_.walls[static_cast<std::size_t>(-j - 1)].name << "'";
  out << " reached " << overlap / radius << " of the radius (limit soft_sphere.max_overlap = "
      << options_.max_overlap << ") at t = " << time_ << " s. Either the step " << time_step_
      << " s is too large (the contact lasts " << shortest_contact_time_ << " s at " << impact_speed_
      << " m/s; take at most 1/50 of it, or raise soft_sphere.impact_speed if impacts are faster)"
      << " or the material is too soft for the load (raise young_modulus or stiffness: the peak "
         "overlap falls as E^-2/5 for Hertz, k^-1/2 for the linear spring)";
  throw MethodFailure("soft_sphere_overlap", out.str());
}

std::size_t SoftSphereEngine::contacts_now() const {
  std::size_t n = 0;
  for (const PairContactState& c : list_.pairs()) n += c.touching;
  for (const WallContactState& c : list_.wall_pairs()) n += c.touching;
  return n;
}

std::vector<MethodQuantity> SoftSphereEngine::quantities() const {
  std::size_t pair_contacts = 0;
  for (const PairContactState& c : list_.pairs()) pair_contacts += c.touching;
  const double n = static_cast<double>(std::max<std::size_t>(system_.particles.size(), 1));
  std::uint64_t ended = 0;
  double total = 0.0;
  const std::size_t S = system_.species.size();
  for (std::size_t s = 0; s < S; ++s)  // booked symmetric: each pair of species once
    for (std::size_t t = s; t < S; ++t) {
      ended += durations_.count[s * S + t];
      total += durations_.total[s * S + t];
    }
  return {
      {"time_step", time_step_, "s", "the velocity-Verlet step"},
      {"shortest_contact_time", shortest_contact_time_, "s", "binary contact time that set the default step"},
      {"impact_speed", impact_speed_, "m/s", "impact speed of the Hertz contact times"},
      {"steps", static_cast<double>(steps_), "", "steps taken since the start"},
      {"neighbour_list_builds", static_cast<double>(list_.builds()), "", "Verlet-list rebuilds"},
      {"coordination_number", 2.0 * static_cast<double>(pair_contacts) / n, "", "particle contacts per particle now"},
      {"wall_contacts", static_cast<double>(contacts_now() - pair_contacts), "", "particle-wall contacts now"},
      {"mean_contact_duration", ended > 0 ? total / static_cast<double>(ended) : 0.0, "s",
       "mean duration of the pair contacts that ended"},
      {"largest_overlap", worst_overlap_, "", "largest overlap seen, over the smaller radius"},
  };
}

}  // namespace carom
