#include "events/event_driven/stall_detector.hpp"

#include <algorithm>
#include <sstream>

namespace carom {

double StallDetector::default_window(const CollapseOptions& options, double smallest_diameter,
                                     double rms_speed, double gravity) {
  if (options.stall_window > 0.0) return options.stall_window;
  const double speed = std::max(rms_speed, std::sqrt(gravity * smallest_diameter));
  return speed > 0.0 ? 1e-9 * smallest_diameter / speed : 0.0;
}

std::string collapse_remedy(const CollapseOptions& options) {
  std::ostringstream out;
  out << "Remedy: ";
  if (options.contact_time > 0.0)
    out << "the TC model is on (collapse contact_time = " << options.contact_time
        << " s): a longer contact_time makes more of these collisions elastic; ";
  else
    out << "turn on the TC model (collapse contact_time, e.g. 1e-5 s: collisions within t_c of "
           "the previous one are elastic); ";
  if (options.elastic_below_speed > 0.0)
    out << "slow impacts are already elastic below " << options.elastic_below_speed
        << " m/s (collapse elastic_below_speed): a higher threshold makes more of them so; ";
  else
    out << "or make slow impacts elastic (collapse elastic_below_speed, e.g. 0.01 m/s); ";
  out << "or raise the restitution coefficient; or, where the particles rest in lasting "
         "contact (a packed or pinned bed), use the soft-sphere method ([method] kind = "
         "\"soft_sphere\", with the species' young_modulus), which models lasting contacts.";
  return out.str();
}

std::string collapse_diagnostic(double t, const std::string& particle, std::uint32_t count,
                                double window, const std::string& partner,
                                const CollapseOptions& options) {
  std::ostringstream out;
  out << "inelastic collapse at t = " << t << " s: " << particle << " took part in " << count
      << " collisions ";
  // Collisions closer than the resolution of t (a spacing below 1e-16 t) all fall at one time.
  if (window > 0.0)
    out << "within " << window << " s";
  else
    out << "at the same time (their spacing fell below the resolution of t)";
  out << ", the last with " << partner
      << ". Hard spheres cannot rest in lasting contact, so the event rate diverges. "
      << collapse_remedy(options);
  return out.str();
}

std::string stuck_diagnostic(double t, std::uint64_t events, const std::string& particle,
                             const CollapseOptions& options) {
  std::ostringstream out;
  out << "the run is stalled at t = " << t << " s: " << events
      << " events without simulated time moving on, the last for " << particle
      << ". This is inelastic collapse or particles at rest in lasting contact. "
      << collapse_remedy(options);
  return out.str();
}

std::string lasting_contact_diagnostic(double t, double frequency, double span,
                                       const CollapseOptions& options) {
  std::ostringstream out;
  out << "lasting contacts at t = " << t << " s: over the last " << span
      << " s each particle collided " << frequency << " times per second on average, above the "
      << "limit of " << options.collision_frequency_limit() << " per second (";
  if (options.max_collision_frequency >= 0.0)
    out << "collapse max_collision_frequency";
  else
    out << options.max_collisions_per_contact_time << " collisions within the TC model's contact_time of "
        << options.contact_time << " s: collapse max_collisions_per_contact_time";
  out << "). The particles rest or are pressed in lasting contact (a packed bed, a plug pinned "
         "under a lid), where binary instantaneous collisions do not describe them: the event "
         "rate grows without bound as their gaps close. Remedy: the soft-sphere method ([method] "
         "kind = \"soft_sphere\", with the species' young_modulus), which models lasting contacts; "
         "or, to run on regardless, raise that limit (0 turns the check off).";
  return out.str();
}

}  // namespace carom
