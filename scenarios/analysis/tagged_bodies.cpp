#include "scenarios/analysis/tagged_bodies.hpp"

#include <limits>

#include <cmath>
#include <sstream>

#include "scenarios/analysis/run_analysis.hpp"
#include "scenarios/run/summary.hpp"

namespace carom {

std::vector<std::pair<std::string, std::size_t>> tagged_series_widths(std::size_t bodies,
                                                                      std::size_t partners) {
  if (bodies == 0) return {};
  return {{"tagged_position", 3 * bodies},
          {"tagged_velocity", 3 * bodies},
          {"tagged_impulse", 3 * bodies * partners},
          {"tagged_force", 3 * bodies},
          {"tagged_force_by_partner", 3 * bodies * partners},
          {"tagged_mean_velocity", 3},
          {"tagged_mean_force", 3}};
}

void sample_tagged_bodies(const CollisionMethod& sim, const double* previous_impulse,
                          double previous_time, SeriesRow& row) {
  const TaggedImpulses& tagged = sim.statistics().tagged;
  const std::size_t T = tagged.body_count(), C = tagged.partners();
  if (T == 0) return;
  // Method index of each body (slot order); a body that left (an outflow) has none.
  constexpr std::size_t kGone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> index(T, kGone);
  for (std::size_t i = 0; i < tagged.slot_of.size(); ++i)
    if (tagged.slot_of[i] >= 0) index[static_cast<std::size_t>(tagged.slot_of[i])] = i;
  const double window = sim.time() - previous_time;
  const bool has_window = previous_impulse != nullptr && window > 0.0;
  std::vector<double> position, velocity, impulse, force, by_partner;
  Vec3 mean_velocity = Vec3::Zero(), mean_force = Vec3::Zero();
  for (std::size_t k = 0; k < T; ++k) {
    const bool gone = index[k] == kGone;
    const Vec3 r = gone ? Vec3::Constant(NAN) : sim.position(index[k]);
    const Vec3 v = gone ? Vec3::Constant(NAN) : sim.velocity(index[k]);
    position.insert(position.end(), {r.x(), r.y(), r.z()});
    velocity.insert(velocity.end(), {v.x(), v.y(), v.z()});
    mean_velocity += v;
    Vec3 total = Vec3::Zero();
    for (std::size_t c = 0; c < C; ++c) {
      const Vec3& J = tagged.impulse[k * C + c];
      impulse.insert(impulse.end(), {J.x(), J.y(), J.z()});
      for (int a = 0; a < 3; ++a) {
        const double f = has_window ? (J[a] - previous_impulse[(k * C + c) * 3 + a]) / window : NAN;
        by_partner.push_back(f);
        total[a] += f;
      }
    }
    force.insert(force.end(), {total.x(), total.y(), total.z()});
    mean_force += total;
  }
  mean_velocity /= static_cast<double>(T);
  mean_force /= static_cast<double>(T);
  row.push_back({"tagged_position", 3 * T, position});
  row.push_back({"tagged_velocity", 3 * T, velocity});
  row.push_back({"tagged_impulse", 3 * T * C, impulse});
  row.push_back({"tagged_force", 3 * T, force});
  row.push_back({"tagged_force_by_partner", 3 * T * C, by_partner});
  row.push_back(
      {"tagged_mean_velocity", 3, {mean_velocity.x(), mean_velocity.y(), mean_velocity.z()}});
  row.push_back({"tagged_mean_force", 3, {mean_force.x(), mean_force.y(), mean_force.z()}});
}

TaggedConclusions conclude_tagged(const std::vector<std::uint64_t>& ids, std::size_t partners,
                                  const std::vector<double>& times,
                                  const std::vector<double>& mean_velocity,
                                  const std::vector<double>& impulse) {
  TaggedConclusions c;
  c.ids = ids;
  c.bodies = ids.size();
  const std::size_t rows = times.size();
  if (c.bodies == 0 || rows == 0 || mean_velocity.size() < 3 * rows) return c;
  const Vec3 first(mean_velocity[0], mean_velocity[1], mean_velocity[2]);
  if (first.norm() > 0.0) c.direction = first.normalized();
  std::vector<double> speed(rows);
  for (std::size_t r = 0; r < rows; ++r)
    speed[r] = Vec3(mean_velocity[3 * r], mean_velocity[3 * r + 1], mean_velocity[3 * r + 2])
                   .dot(c.direction);
  c.start_speed = speed.front();
  c.end_speed = speed.back();
  const std::size_t width = 3 * c.bodies * partners;
  const double duration = times.back() - times.front();
  if (duration > 0.0 && impulse.size() >= width * rows) {
    Vec3 change = Vec3::Zero();
    for (std::size_t e = 0; e < c.bodies * partners; ++e)
      for (int a = 0; a < 3; ++a)
        change[a] += impulse[(rows - 1) * width + 3 * e + a] - impulse[3 * e + a];
    c.mean_force = change / (duration * static_cast<double>(c.bodies));
  }
  c.fit = fit_inverse_speed(times, speed);
  return c;
}

std::string tagged_json(const TaggedConclusions& c) {
  std::ostringstream j;
  j << "{\"bodies\": " << c.bodies << ", \"ids\": [";
  for (std::size_t k = 0; k < c.ids.size(); ++k) j << (k ? ", " : "") << c.ids[k];
  const auto vec = [](const Vec3& v) {
    return "[" + json_number(v.x()) + ", " + json_number(v.y()) + ", " + json_number(v.z()) + "]";
  };
  j << "], \"direction\": " << vec(c.direction)
    << ", \"start_speed\": " << json_number(c.start_speed)
    << ", \"end_speed\": " << json_number(c.end_speed) << ", \"mean_force\": " << vec(c.mean_force)
    << ", \"mean_force_along_direction\": " << json_number(c.mean_force.dot(c.direction))
    << ", \"inverse_speed_fit\": {\"valid\": " << (c.fit.valid ? "true" : "false")
    << ", \"k\": " << json_number(c.fit.valid ? c.fit.k : NAN)
    << ", \"k_error\": " << json_number(c.fit.valid ? c.fit.k_error : NAN)
    << ", \"intercept\": " << json_number(c.fit.valid ? c.fit.intercept : NAN)
    << ", \"intercept_error\": " << json_number(c.fit.valid ? c.fit.intercept_error : NAN)
    << ", \"points\": " << c.fit.points << "}}";
  return j.str();
}

std::string tagged_report(const TaggedConclusions& c) {
  if (c.bodies == 0) return "";
  std::ostringstream r;
  r.precision(4);
  r << "\n## Tagged bodies\n\n"
    << c.bodies << " tagged bod" << (c.bodies == 1 ? "y" : "ies") << " (ids";
  for (std::uint64_t id : c.ids) r << " " << id;
  r << "). Their mean speed along the initial direction went from " << c.start_speed << " m/s to "
    << c.end_speed
    << " m/s; the mean collision force on one body over the record, along that direction, was "
    << c.mean_force.dot(c.direction) << " N.\n";
  if (c.fit.valid)
    r << "\nFit of 1/V = 1/V0 + k t (" << c.fit.points << " samples): k = " << c.fit.k << " +- "
      << c.fit.k_error << " 1/m, 1/V0 = " << c.fit.intercept << " +- " << c.fit.intercept_error
      << " s/m (a drag force m k V^2 on each body).\n";
  return r.str();
}

}  // namespace carom
