#pragma once
/// The next time of a periodic or synchronising action registered on a method rebuilt from a
/// checkpoint: the saved time of the action of that name continues the schedule exactly.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/display_number.hpp"

namespace carom {

/// The saved next time of action `name` in `saved`, else `first_time` (the caller's, for a new
/// action). A saved time fires once the method reaches it, so it lies at or after the state's
/// time `now` and at most one `interval` after the later of `now` and `first_time` (an action
/// that has fired is due again within one interval). Anything else cannot come from a run of
/// this scene (a time before `now` would send the method's clock back): std::invalid_argument,
/// which a resume reports as a checkpoint it cannot continue from.
inline double restored_next_time(const std::vector<std::pair<std::string, double>>& saved,
                                 const std::string& name, double first_time, double now, double interval) {
  for (const auto& [saved_name, saved_time] : saved) {
    if (saved_name != name) continue;
    const double latest = std::max(now, first_time) + interval * (1.0 + 1e-9);
    if (!(saved_time >= now && saved_time <= latest))
      throw std::invalid_argument("saved state: the next " + name + " at t = " + display_number(saved_time) +
                                  " s is not between the state's time " + display_number(now) + " s and " +
                                  display_number(latest) + " s (one interval of " + display_number(interval) +
                                  " s later)");
    return saved_time;
  }
  return first_time;
}

}  // namespace carom
