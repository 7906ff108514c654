// Exact event predictions for ballistic flights: pairs, walls, cylinder, grid cells.
#include <algorithm>

#include "core/roots.hpp"
#include "simulator.hpp"

namespace carom {

double Simulator::pair_time(std::int32_t i, std::int32_t j) const {
  const ParticleStore& p = system_.particles;
  // Both states are taken to the later of the two clocks: the result depends only on the
  // stored states (not on when the prediction is made), and is symmetric in i and j.
  const double t_ref = std::max(p.clock[i], p.clock[j]);
  const double dt_i = t_ref - p.clock[i], dt_j = t_ref - p.clock[j];
  Vec3 dr = p.position[i] - p.position[j] + dt_i * p.velocity[i] - dt_j * p.velocity[j];
  Vec3 dv = p.velocity[i] - p.velocity[j];
  if (has_gravity_) {
    const Vec3& g = system_.flight.gravity;
    dr += (0.5 * (dt_i * dt_i - dt_j * dt_j)) * g;
    dv += (dt_i - dt_j) * g;
  }
  system_.domain.minimum_image(dr);
  const double s = sphere_contact_time(dr, dv, p.radius[i] + p.radius[j]);
  return t_ref + s;
}

double Simulator::wall_time(std::int32_t i, const Wall& wall) const {
  const ParticleStore& p = system_.particles;
  const Vec3& r = p.position[i];
  const Vec3& v = p.velocity[i];
  double s;
  if (wall.shape == Wall::Shape::Plane) {
    // Gap h(s) = h0 + (v.n) s + (g.n) s^2/2; contact when h falls through zero.
    const double gap = (r - wall.point).dot(wall.normal) - p.radius[i];
    s = first_upward_crossing(-0.5 * system_.flight.gravity.dot(wall.normal), -v.dot(wall.normal), -gap);
  } else {
    // Horizontal motion is linear (gravity is along the axis): |d + u s|^2 = (R - a)^2.
    const double dx = r.x() - wall.point.x(), dy = r.y() - wall.point.y();
    const double reach = wall.radius - p.radius[i];
    s = first_upward_crossing(v.x() * v.x() + v.y() * v.y(), 2.0 * (dx * v.x() + dy * v.y()),
                              dx * dx + dy * dy - reach * reach);
  }
  return p.clock[i] + s;
}

void Simulator::cell_crossing(std::int32_t i, Event& best) const {
  const ParticleStore& p = system_.particles;
  const Vec3 lower = grid_.cell_lower(i), upper = grid_.cell_upper(i);
  const Vec3& r = p.position[i];
  const Vec3& v = p.velocity[i];
  const Vec3& g = system_.flight.gravity;
  for (int k = 0; k < 3; ++k) {
    if (!grid_.is_outer_face(i, k, +1)) {
      const double t = p.clock[i] + first_upward_crossing(0.5 * g[k], v[k], r[k] - upper[k]);
      if (t < best.time) best = Event{t, 2 * k + 1, 0, EventKind::CellCrossing};
    }
    if (!grid_.is_outer_face(i, k, -1)) {
      const double t = p.clock[i] + first_upward_crossing(-0.5 * g[k], -v[k], lower[k] - r[k]);
      if (t < best.time) best = Event{t, 2 * k, 0, EventKind::CellCrossing};
    }
  }
}

void Simulator::predict(std::int32_t i) {
  const ParticleStore& p = system_.particles;
  Event best;
  cell_crossing(i, best);
  for (std::size_t w = 0; w < system_.walls.size(); ++w) {
    const double t = wall_time(i, system_.walls[w]);
    if (t < best.time) best = Event{t, static_cast<std::int32_t>(w), 0, EventKind::Wall};
  }
  grid_.for_each_candidate(i, p.radius[i], [&](std::int32_t j) {
    const double t = pair_time(i, j);
    if (t < best.time) best = Event{t, j, p.event_counter[j], EventKind::Pair};
  });
  // Round-off may put a root a hair before the last event: nothing happens in the past.
  if (best.time < last_particle_event_) best.time = last_particle_event_;
  events_[i] = best;
  calendar_.set(static_cast<std::size_t>(i), best.time);
}

}  // namespace carom
