#include "scenarios/scene/impact_speed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace carom {

double default_impact_speed(const System& system) {
  const double g = system.flight.gravity.norm();
  if (g == 0.0 || system.species.empty()) return 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const Species& s : system.species) smallest = std::min(smallest, s.diameter);
  return kImpactSpeedFraction * std::sqrt(g * smallest);
}

}  // namespace carom
