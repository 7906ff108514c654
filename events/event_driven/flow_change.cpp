// Particles leaving and entering the event-driven engine (inflow, outflow): at a flow step every
// particle stands at the step's time, so the engine's per-particle records, grid and calendar
// are rebuilt for the new set of particles, as at construction but without reordering them.
#include <algorithm>
#include <cmath>

#include "events/event_driven/engine.hpp"
#include "events/particle_change.hpp"

namespace carom {

void EventDrivenEngine::apply_change(const ParticleChange& change) {
  check_particle_change(change, system_, time_);
  ParticleStore& p = system_.particles;
  flow_energy_ += change_energy(change, p, system_.flight.gravity);

  // What survivors keep: their last collision (TC model), stall records and event counters.
  std::vector<double> last_collision(body_.size());
  for (std::size_t i = 0; i < body_.size(); ++i) last_collision[i] = body_[i].last_collision;
  follow_change(last_collision, change, -kNever);
  follow_change(agenda_, change, Agenda{});
  follow_change(counter_, change, std::uint32_t{0});
  follow_change(flights_, change, RelaxFlight{0.0, system_.flight.gravity});
  apply_particle_change(change, p, statistics_.tagged);
  const std::size_t n = p.size();

  hot_.assign(n, HotState{});
  body_.assign(n, Body{});
  for (std::size_t i = 0; i < n; ++i) {
    body_[i].last_collision = last_collision[i];
    load_records(static_cast<std::int32_t>(i));
  }
  grid_ = HierarchicalGrid(system_.domain, p.radius, options_.grid_level_ratio,
                           options_.grid_subdivision);
  for (std::size_t i = 0; i < n; ++i) grid_.insert(static_cast<std::int32_t>(i), p.position[i]);
  reset_cell_speeds();
  reset_level_speeds();
  reset_candidate_memos();  // the indices have moved

  // The calendar: particle slots 0..n-1, the end of the current run_until at n, the actions
  // after it (their order, and so the order of ties, is kept).
  const double end_time = calendar_.time_of(end_slot_);
  end_slot_ = n;
  calendar_ = Calendar(n + 1 + actions_.size());
  calendar_.set(end_slot_, end_time);
  for (std::size_t k = 0; k < actions_.size(); ++k)
    calendar_.set(end_slot_ + 1 + k, actions_[k].next_time);

  if (stall_.window <= 0.0 && n > 0) {  // a run that started empty: its first particles set it
    double mean_square = 0.0;
    for (const Vec3& v : p.velocity) mean_square += v.squaredNorm();
    stall_.window = StallDetector::default_window(
        options_.collapse, 2.0 * *std::min_element(p.radius.begin(), p.radius.end()),
        std::sqrt(mean_square / double(n)), system_.flight.gravity.norm());
  }
}

}  // namespace carom
