#include "events/flow/flow_boundaries.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "events/flow/inflow_placement.hpp"

namespace carom {

namespace {

/// The inflows' stream: the scene's seed moved on by a constant of its own, so that it shares
/// no numbers with the placement (the seed itself) or the Monte Carlo collisions.
constexpr std::uint64_t kFlowStream = 0xd1b54a32d192ed03ULL;

[[noreturn]] void fail(const std::string& what, const std::string& name, const FlowProblem& p) {
  throw std::invalid_argument(what + " \"" + name + "\": " + p.key + " " + p.problem);
}

void check_unique(const std::vector<std::string>& names, const std::string& what) {
  for (std::size_t a = 0; a < names.size(); ++a)
    for (std::size_t b = a + 1; b < names.size(); ++b)
      if (names[a] == names[b])
        throw std::invalid_argument("two " + what + "s are called \"" + names[a] +
                                    "\"; give each a name of its own");
}

}  // namespace

FlowBoundaries::FlowBoundaries(std::vector<Inflow> inflows, std::vector<Outflow> outflows,
                               const System& system, std::uint64_t seed, double start_time,
                               double interval)
    : inflows_(std::move(inflows)),
      outflows_(std::move(outflows)),
      domain_(system.domain),
      walls_(system.walls),
      species_(system.species),
      gravity_(system.flight.gravity),
      rng_(seed ^ kFlowStream),
      start_time_(start_time),
      last_time_(start_time) {
  std::vector<std::string> inflow_names, outflow_names;
  for (const Outflow& out : outflows_) {
    if (auto problem = check_outflow(out, domain_)) fail("outflow", out.name, *problem);
    outflow_names.push_back(out.name);
  }
  for (Inflow& in : inflows_) {
    if (auto problem = check_inflow(in, system, interval)) fail("inflow", in.name, *problem);
    in.depth = inflow_depth(in, species_[in.species], interval);
    for (const Outflow& out : outflows_)
      if (auto problem = check_inflow_against_outflow(in, in.depth, out))
        fail("inflow", in.name, *problem);
    inflow_names.push_back(in.name);
  }
  check_unique(inflow_names, "inflow");
  check_unique(outflow_names, "outflow");
  inflow_counters_.resize(inflows_.size());
  outflow_counters_.resize(outflows_.size());
  particle_seconds_.assign(species_.size(), 0.0);
  present_.assign(species_.size(), 0);
  const ParticleStore& p = system.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    ++present_.at(p.species[i]);
    next_id_ = std::max(next_id_, p.id[i] + 1);
  }
}

double FlowBoundaries::energy(double mass, double inertia, const Vec3& r, const Vec3& v,
                              const Vec3& w) const {
  Vec3 folded = r;
  for (int k = 0; k < 3; ++k) {
    if (!domain_.periodic[k]) continue;
    const double length = domain_.upper[k] - domain_.lower[k];
    folded[k] = domain_.lower[k] + std::fmod(folded[k] - domain_.lower[k], length);
    if (folded[k] < domain_.lower[k]) folded[k] += length;
  }
  return 0.5 * mass * v.squaredNorm() + 0.5 * inertia * w.squaredNorm() -
         mass * gravity_.dot(folded);
}

void FlowBoundaries::step(double time, const ParticleStore& particles, ParticleChange& change) {
  if (!(time >= last_time_))
    throw std::invalid_argument("flow step at t = " + std::to_string(time) +
                                " s, before the last one (" + std::to_string(last_time_) + " s)");
  const std::size_t n = particles.size();
  const std::size_t species_count = species_.size();

  // Particle-seconds with the counts before any change; the largest id ever seen.
  std::vector<std::uint64_t> count(species_count, 0);
  for (std::size_t i = 0; i < n; ++i) {
    ++count.at(particles.species[i]);
    next_id_ = std::max(next_id_, particles.id[i] + 1);
  }
  for (std::size_t s = 0; s < species_count; ++s)
    particle_seconds_[s] += static_cast<double>(count[s]) * (time - last_time_);

  // Outflow: each particle beyond an outlet leaves once, booked to the first outlet it is beyond.
  std::vector<char> leaving(n, 0);
  for (std::size_t i : change.removed) leaving.at(i) = 1;
  std::vector<std::size_t> removed;
  for (std::size_t i = 0; i < n; ++i) {
    if (leaving[i]) continue;
    for (std::size_t k = 0; k < outflows_.size(); ++k) {
      if (!beyond(outflows_[k], particles.position[i])) continue;
      leaving[i] = 1;
      removed.push_back(i);
      OutflowCounters& c = outflow_counters_[k];
      ++c.left;
      c.left_mass += particles.mass[i];
      energy_out_ += energy(particles.mass[i], particles.inertia[i], particles.position[i],
                            particles.velocity[i], particles.spin[i]);
      break;
    }
  }
  if (!removed.empty()) {
    std::vector<std::size_t> before = std::move(change.removed);
    std::sort(before.begin(), before.end());
    change.removed.clear();
    std::set_union(before.begin(), before.end(), removed.begin(), removed.end(),
                   std::back_inserter(change.removed));
    change.removed.erase(std::unique(change.removed.begin(), change.removed.end()),
                         change.removed.end());
  }

  // Inflow: the obstacles are the particles that stay and those entering.
  double max_radius = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    if (!leaving[i]) max_radius = std::max(max_radius, particles.radius[i]);
  for (double a : change.added.radius) max_radius = std::max(max_radius, a);
  for (std::size_t k = 0; k < inflows_.size(); ++k) {
    run_inflow(k, time, particles, leaving, max_radius, change);
    max_radius = std::max(max_radius, species_[inflows_[k].species].radius());
  }

  std::fill(present_.begin(), present_.end(), 0);
  for (std::size_t i = 0; i < n; ++i)
    if (!leaving[i]) ++present_[particles.species[i]];
  for (std::uint32_t s : change.added.species) ++present_.at(s);
  for (std::uint64_t id : change.added.id) next_id_ = std::max(next_id_, id + 1);
  last_time_ = time;
}

void FlowBoundaries::run_inflow(std::size_t k, double time, const ParticleStore& particles,
                                const std::vector<char>& leaving, double obstacles_max_radius,
                                ParticleChange& change) {
  const Inflow& in = inflows_[k];
  const Species& kind = species_[in.species];
  const double mass = kind.mass();
  InflowCounters& c = inflow_counters_[k];
  // Owed since the start, from one product (no sum of steps): over any window the mass in is
  // the set rate's within one particle.
  const double due = in.mass_flow * (time - start_time_) / mass;
  const double whole = std::floor(due) - static_cast<double>(c.entered);
  if (whole >= 1.0) {
    const auto wanted = static_cast<std::uint64_t>(whole);
    SlabPlacer placer(inflow_centres(in, in.depth, kind.radius()), kind.radius(),
                      obstacles_max_radius, domain_, walls_);
    for (std::size_t i = 0; i < particles.size(); ++i)
      if (!leaving[i]) placer.add(particles.position[i], particles.radius[i]);
    for (std::size_t j = 0; j < change.added.size(); ++j)
      placer.add(change.added.position[j], change.added.radius[j]);
    for (std::uint64_t placed = 0; placed < wanted; ++placed) {
      Vec3 r;
      if (!placer.place(rng_, in.attempts, r)) {
        // The slab is full: this one and the rest wait for the next step.
        ++c.blocked_steps;
        break;
      }
      const Vec3 v = in.velocity + in.velocity_spread.cwiseProduct(rng_.normal3());
      change.added.add(r, v, Vec3::Zero(), kind.radius(), mass, kind.inertia(), in.species,
                       next_id_++, time);
      ++c.entered;
      energy_in_ += energy(mass, kind.inertia(), r, v, Vec3::Zero());
    }
    c.failed_tries += placer.failed_tries();
  }
  c.entered_mass = static_cast<double>(c.entered) * mass;
  c.owed = due - static_cast<double>(c.entered);
}

std::string FlowBoundaries::blocked_message(std::size_t k) const {
  const InflowCounters& c = inflow_counters_[k];
  if (c.blocked_steps == 0) return "";
  const Inflow& in = inflows_[k];
  return "inflow \"" + in.name + "\" found its slab full at " + std::to_string(c.blocked_steps) +
         " flow step(s) (" + std::to_string(c.failed_tries) + " random places tried were taken); " +
         std::to_string(c.waiting()) + " particle(s) still wait, " + std::to_string(c.entered) +
         " entered: the mass that entered is less than mass_flow asks. Lower mass_flow, enlarge "
         "the rectangle or the depth, or give the particles a speed into the domain";
}

std::vector<double> FlowBoundaries::particle_seconds_at(double time) const {
  std::vector<double> total = particle_seconds_;
  for (std::size_t s = 0; s < total.size(); ++s)
    total[s] += static_cast<double>(present_[s]) * (time - last_time_);
  return total;
}

std::uint64_t FlowBoundaries::present_total() const {
  std::uint64_t total = 0;
  for (std::uint64_t c : present_) total += c;
  return total;
}

}  // namespace carom
