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

std::string collapse_diagnostic(double t, const std::string& particle, std::uint32_t count,
                                double window, const std::string& partner) {
  std::ostringstream out;
  out << "inelastic collapse at t = " << t << " s: " << particle << " took part in " << count
      << " collisions within " << window << " s, the last with " << partner
      << ". Hard spheres cannot rest in lasting contact, so the event rate diverges. Remedy: "
         "turn on the TC model (collapse contact_time, e.g. 1e-5 s: collisions within t_c of "
         "the previous one are elastic), or make slow impacts elastic (collapse "
         "elastic_below_speed), or raise the restitution coefficient.";
  return out.str();
}

std::string stuck_diagnostic(double t, std::uint64_t events, const std::string& particle) {
  std::ostringstream out;
  out << "the run is stalled at t = " << t << " s: " << events
      << " events without simulated time moving on, the last for " << particle
      << ". This is inelastic collapse or particles at rest in lasting contact. Remedy: turn "
         "on the TC model (collapse contact_time, e.g. 1e-5 s), or make slow impacts elastic "
         "(collapse elastic_below_speed).";
  return out.str();
}

}  // namespace carom
