#pragma once
/// The one decision of which law a collision obeys: the pair's (or wall's) Walton law, unless a
/// collapse remedy (the TC model, elastic slow impacts) replaces it. The event-driven method calls
/// this; the Monte Carlo method applies the low-speed rule to its wall impacts itself
/// (particle_step.cpp); soft spheres use neither remedy.
#include <cmath>

#include "core/contact_law.hpp"
#include "events/laws/collapse.hpp"

namespace carom {

/// The law of a collision at time t (s) with normal approach speed `normal_speed` (m/s) between
/// bodies whose previous collisions were at last_1 and last_2 (s; a wall: -kNever):
///   TC model: e = 1, mu = 0 (elastic and smooth) when either collided less than t_c ago;
///   low-speed rule: e = 1 (friction kept) when |g_n| < elastic_below_speed;
///   otherwise `law` itself.
inline ContactLaw effective_law(const ContactLaw& law, const CollapseOptions& collapse,
                                double normal_speed, double t, double last_1, double last_2) {
  if (collapse.contact_time > 0.0 &&
      (t - last_1 < collapse.contact_time || t - last_2 < collapse.contact_time)) {
    ContactLaw elastic_smooth;  // e = 1, mu = 0: no energy lost, no tangential impulse
    return elastic_smooth;
  }
  if (std::abs(normal_speed) < collapse.elastic_below_speed) {
    ContactLaw elastic = law;
    elastic.restitution = 1.0;
    return elastic;
  }
  return law;
}

}  // namespace carom
